// DecomposeOptions::progress: called after every committed split, on the
// calling thread, with a count that grows by one up to N; it changes nothing.
#include <doctest/doctest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/poly_io.hpp"

TEST_SUITE("decompose") {

TEST_CASE("progress: called on the calling thread after each split, done 2..N, result unchanged") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/pipe.poly");
  for (const unsigned threads : {1u, 3u}) {
    for (const std::uint32_t n : {1u, 2u, 7u, 100u}) {
      CAPTURE(threads);
      CAPTURE(n);
      madd::DecomposeOptions options;
      options.subdomains = n;
      options.threads = threads;
      const madd::Decomposition plain = madd::decompose(domain, options);
      std::vector<std::uint32_t> done;
      bool same_thread = true, same_target = true;
      const std::thread::id caller = std::this_thread::get_id();
      options.progress = [&](std::uint32_t d, std::uint32_t target) {
        done.push_back(d);
        same_thread = same_thread && std::this_thread::get_id() == caller;
        same_target = same_target && target == n;
      };
      CHECK(madd::decompose(domain, options) == plain);
      CHECK(same_thread);
      CHECK(same_target);
      REQUIRE(done.size() == n - 1);  // one call per split
      for (std::size_t k = 0; k < done.size(); ++k) CHECK(done[k] == k + 2);
    }
  }
}

TEST_CASE("progress: an exception from the callback stops decompose and comes out of it") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  madd::DecomposeOptions options;
  options.subdomains = 64;
  options.threads = 2;
  std::uint32_t calls = 0;
  options.progress = [&](std::uint32_t done, std::uint32_t) {
    ++calls;
    if (done == 10) throw std::runtime_error("cancelled at 10");
  };
  CHECK_THROWS_WITH_AS(madd::decompose(domain, options), "cancelled at 10", std::runtime_error);
  CHECK(calls == 9);
}

TEST_CASE("progress: with a required area, target is the maximum and done the count so far") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  madd::DecomposeOptions options;
  options.subdomains = 500;
  options.subdomain_area_function = [](double x, double) { return x < 0.5 ? 0.02 : 0.2; };
  const madd::Decomposition plain = madd::decompose(domain, options);
  std::vector<std::uint32_t> done;
  options.progress = [&](std::uint32_t d, std::uint32_t target) {
    CHECK(target == 500);
    done.push_back(d);
  };
  CHECK(madd::decompose(domain, options) == plain);
  REQUIRE(!done.empty());
  for (std::size_t k = 0; k < done.size(); ++k) CHECK(done[k] == k + 2);
  CHECK(done.back() == plain.subdomains.size());
}

}  // TEST_SUITE("decompose")
