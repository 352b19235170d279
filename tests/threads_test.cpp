// run_on_threads (kernel/threads.hpp): every id once, on parked helpers the
// process keeps between steps, nested and concurrent steps served by threads
// of their own, exceptions rethrown, and a child after fork() able to run.
#include <doctest/doctest.h>

#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <string>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "kernel/threads.hpp"

namespace {

long os_thread_id() { return static_cast<long>(::syscall(SYS_gettid)); }

// The OS thread ids of the process's threads (/proc/self/task).
std::set<long> process_threads() {
  std::set<long> out;
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task"))
    out.insert(std::stol(entry.path().filename().string()));
  return out;
}

// Runs one step of n ids; returns the OS thread each id ran on.
std::vector<long> step(unsigned n) {
  std::vector<long> on(n, 0);
  std::vector<int> times(n, 0);
  madd::detail::run_on_threads(n, [&](unsigned id) {
    on[id] = os_thread_id();
    ++times[id];
  });
  for (unsigned id = 0; id < n; ++id) CHECK(times[id] == 1);
  return on;
}

}  // namespace

TEST_SUITE("threads") {

TEST_CASE("run_on_threads: each id once, id 0 on the caller, the others on distinct threads") {
  for (const unsigned n : {1u, 2u, 3u, 8u}) {
    CAPTURE(n);
    const std::vector<long> on = step(n);
    CHECK(on[0] == os_thread_id());
    CHECK(std::set<long>(on.begin(), on.end()).size() == n);
  }
}

TEST_CASE("run_on_threads: the helpers are parked between steps, not made again") {
  // A step of 32 ids makes the helpers up to 32 (one spare, for the files'
  // writer) and uses 31 of them. Threads made for every step would add
  // tasks to the process; parked ones answer the later steps themselves.
  const std::vector<long> all = step(32);
  const std::set<long> helpers(all.begin() + 1, all.end());
  REQUIRE(helpers.size() == 31);
  const std::set<long> tasks = process_threads();
  for (const long helper : helpers) CHECK(tasks.count(helper) == 1);
  for (int k = 0; k < 20; ++k)
    for (const unsigned n : {2u, 3u, 8u, 31u}) {
      const std::vector<long> again = step(n);
      for (unsigned id = 1; id < n; ++id) CHECK(tasks.count(again[id]) == 1);
    }
  CHECK(process_threads() == tasks);
}

TEST_CASE("run_on_threads: a nested step and a second caller's step run all their ids") {
  std::atomic<int> inner{0};
  madd::detail::run_on_threads(3, [&](unsigned) {
    madd::detail::run_on_threads(2, [&](unsigned) { ++inner; });  // the helpers are busy: threads of its own
  });
  CHECK(inner == 6);
  std::atomic<int> ran{0};
  std::vector<std::thread> callers;
  for (int c = 0; c < 4; ++c)
    callers.emplace_back([&] {
      for (int k = 0; k < 50; ++k) madd::detail::run_on_threads(2, [&](unsigned) { ++ran; });
    });
  for (std::thread& t : callers) t.join();
  CHECK(ran == 4 * 50 * 2);
}

TEST_CASE("run_on_threads: an exception from any id is rethrown once all returned, and the helpers still serve") {
  for (const unsigned thrower : {0u, 1u, 2u}) {
    CAPTURE(thrower);
    std::atomic<int> finished{0};
    CHECK_THROWS_WITH_AS(madd::detail::run_on_threads(3,
                                                      [&](unsigned id) {
                                                        if (id == thrower) throw std::runtime_error("id failed");
                                                        std::this_thread::sleep_for(std::chrono::milliseconds(5));
                                                        ++finished;
                                                      }),
                         "id failed", std::runtime_error);
    CHECK(finished == 2);  // the others ran to the end before the rethrow
  }
  CHECK(step(3).size() == 3);
}

TEST_CASE("run_on_threads: a child after fork() has no parked helpers and makes its own") {
  (void)step(3);  // the parent's helpers exist
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    // The parent's helpers are not in this process: a step waiting on them would hang.
    std::atomic<int> ran{0};
    madd::detail::run_on_threads(3, [&](unsigned) { ++ran; });
    ::_exit(ran == 3 ? 0 : 1);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}

}  // TEST_SUITE("threads")
