// Meshing in shares (madd::mesh_share, include/madd/mesh_share.hpp): the
// shares of 1, 2 and 3 processes, run here as threads meeting at an
// in-process collective, together make mesh()'s mesh exactly, vertex ids
// and triangle ids included, whatever the number of shares.
#include <doctest/doctest.h>

#include <algorithm>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "madd/mesh.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_part_output.hpp"
#include "madd/mesh_share.hpp"
#include "madd/poly_io.hpp"
#include "kernel/resource_limits.hpp"
#include "mesh/discretise.hpp"
#include "mesh/rounds.hpp"
#include "mesh/subdomain_regions.hpp"
#include "mesh/work.hpp"
#include "quality/area_bound.hpp"
#include "interior_fixture.hpp"
#include "mesh_fixtures.hpp"

namespace {

// An all-to-all meeting of `n` threads: each brings a vector, each leaves
// with every one's, in share order (what MPI_Allgatherv does).
class Meeting {
public:
  explicit Meeting(std::uint32_t n) : n_(n), brought_(n) {}

  template <typename T>
  std::vector<std::vector<T>> all_gather(std::uint32_t share, const std::vector<T>& mine) {
    std::unique_lock lock(mutex_);
    const std::uint64_t round = round_;
    brought_[share] = [mine](void* out) { *static_cast<std::vector<T>*>(out) = mine; };
    if (++arrived_ == n_) {
      gathered_ = brought_;
      arrived_ = 0;
      ++round_;
      wake_.notify_all();
    } else {
      wake_.wait(lock, [&] { return round_ != round; });
    }
    std::vector<std::vector<T>> all(n_);
    for (std::uint32_t r = 0; r < n_; ++r) gathered_[r](&all[r]);
    return all;
  }

private:
  std::uint32_t n_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::uint32_t arrived_ = 0;
  std::uint64_t round_ = 0;
  std::vector<std::function<void(void*)>> brought_, gathered_;
};

madd::ShareExchange exchange_for(Meeting& meeting, std::uint32_t share, int& rounds_with_splits) {
  madd::ShareExchange x;
  x.union_of = [&meeting, share, &rounds_with_splits](const std::vector<std::uint32_t>& mine) {
    std::vector<std::uint32_t> all;
    for (const auto& theirs : meeting.all_gather(share, mine)) all.insert(all.end(), theirs.begin(), theirs.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (share == 0 && !all.empty()) ++rounds_with_splits;
    return all;
  };
  x.sum_of = [&meeting, share](const std::vector<std::uint64_t>& mine) {
    std::vector<std::uint64_t> sum(mine.size(), 0);
    for (const auto& theirs : meeting.all_gather(share, mine))
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += theirs[i];
    return sum;
  };
  return x;
}

std::vector<madd::MeshPart> mesh_decomposition_in_shares(const madd::Decomposition& d, const madd::Pslg& domain,
                                                         const madd::MeshOptions& o, std::uint32_t shares,
                                                         int& rounds_with_splits) {
  Meeting meeting(shares);
  std::vector<madd::MeshPart> parts(shares);
  std::vector<std::thread> threads;
  for (std::uint32_t r = 0; r < shares; ++r)
    threads.emplace_back([&, r] {
      parts[r] = madd::mesh_share(d, domain, o, r, shares, exchange_for(meeting, r, rounds_with_splits)).part;
    });
  for (std::thread& t : threads) t.join();
  return parts;
}

std::vector<madd::MeshPart> mesh_in_shares(const madd::Pslg& domain, const madd::MeshOptions& o, std::uint32_t shares,
                                           int& rounds_with_splits) {
  const madd::Decomposition d = madd::decompose_for_mesh(domain, o).decomposition;
  return mesh_decomposition_in_shares(d, domain, o, shares, rounds_with_splits);
}

// Every part's vertices and triangles are mesh()'s under their global ids,
// and every triangle of the whole mesh is in exactly one part.
void check_union_is(const madd::Mesh& whole, const std::vector<madd::MeshPart>& parts) {
  std::vector<int> seen(whole.triangles.size(), 0);
  for (const madd::MeshPart& part : parts) {
    REQUIRE(part.total_points == whole.points.size());
    REQUIRE(part.total_triangles == whole.triangles.size());
    const madd::LocalMesh& m = part.mesh;
    REQUIRE(part.point_ids.size() == m.points.size());
    REQUIRE(part.triangle_ids.size() == m.triangles.size());
    for (std::size_t v = 0; v < m.points.size(); ++v) {
      REQUIRE(part.point_ids[v] < whole.points.size());
      CHECK(m.points[v] == whole.points[part.point_ids[v]]);
      CHECK(m.point_markers[v] == whole.point_markers[part.point_ids[v]]);
    }
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const std::uint64_t g = part.triangle_ids[t];
      REQUIRE(g < whole.triangles.size());
      ++seen[g];
      for (int i = 0; i < 3; ++i) CHECK(part.point_ids[m.triangles[t][i]] == whole.triangles[g][i]);
      CHECK(m.triangle_subdomain[t] == whole.triangle_subdomain[g]);
      if (!whole.triangle_attribute.empty()) CHECK(m.triangle_attribute.at(t) == whole.triangle_attribute[g]);
      CHECK(part.owner[m.triangle_subdomain[t]] == part.share);
    }
  }
  CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<std::ptrdiff_t>(seen.size()));
  // Joined, in any order, they are mesh()'s mesh (neighbours, segments, shortfall and all).
  CHECK(madd::join_parts(parts) == whole);
  const std::vector<madd::MeshPart> reversed(parts.rbegin(), parts.rend());
  CHECK(madd::join_parts(reversed) == whole);
}

// A vertex's owner is the lowest share whose part has it.
void check_owners(const std::vector<madd::MeshPart>& parts) {
  std::vector<std::set<std::uint64_t>> has(parts.size());
  for (std::size_t r = 0; r < parts.size(); ++r) has[r].insert(parts[r].point_ids.begin(), parts[r].point_ids.end());
  for (const madd::MeshPart& part : parts)
    for (std::size_t v = 0; v < part.point_ids.size(); ++v) {
      std::uint32_t lowest = 0;
      while (!has[lowest].count(part.point_ids[v])) ++lowest;
      CHECK(part.point_owner[v] == lowest);
    }
}

// The parts' figures combine into the whole mesh's as madd-mpi combines
// them: counts add up, the smallest angle and the largest subdomain are the extremes.
void check_figures_combine(const madd::Mesh& whole, const std::vector<madd::MeshPart>& parts) {
  const madd::MeshMetrics all = madd::mesh_metrics(whole);
  madd::MeshMetrics sum;
  sum.smallest_angle_histogram = {};
  for (const madd::MeshPart& part : parts) {
    const madd::MeshMetrics m = madd::mesh_metrics(part.mesh);
    CHECK(m.subdomains == all.subdomains);
    sum.triangles += m.triangles;
    sum.below_bound += m.below_bound;
    sum.smallest_angle_deg = std::min(sum.smallest_angle_deg, m.smallest_angle_deg);
    sum.largest_subdomain_triangles = std::max(sum.largest_subdomain_triangles, m.largest_subdomain_triangles);
    sum.shortfall.input_angle += m.shortfall.input_angle;
    sum.shortfall.separator += m.shortfall.separator;
    sum.shortfall.precision += m.shortfall.precision;
    sum.shortfall.limit += m.shortfall.limit;
    for (std::size_t b = 0; b < sum.smallest_angle_histogram.size(); ++b)
      sum.smallest_angle_histogram[b] += m.smallest_angle_histogram[b];
  }
  CHECK(sum.triangles == all.triangles);
  CHECK(sum.below_bound == all.below_bound);
  CHECK(sum.smallest_angle_deg == all.smallest_angle_deg);
  CHECK(sum.largest_subdomain_triangles == all.largest_subdomain_triangles);
  CHECK(sum.shortfall == all.shortfall);
  CHECK(sum.smallest_angle_histogram == all.smallest_angle_histogram);
}

}  // namespace

TEST_CASE("mesh_share: 1, 2 and 3 shares of the key make mesh()'s mesh, ids included, and own their vertices once") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/key.poly");
  const madd::MeshOptions o = madd::test::options_for(8, 30, madd::domain_area(domain) / 3000);
  const madd::Mesh whole = madd::mesh(domain, o);
  for (std::uint32_t shares = 1; shares <= 3; ++shares) {
    CAPTURE(shares);
    int rounds = 0;
    const std::vector<madd::MeshPart> parts = mesh_in_shares(domain, o, shares, rounds);
    check_union_is(whole, parts);
    check_owners(parts);
    std::size_t subdomains = 0;
    for (const madd::MeshPart& p : parts) subdomains += p.subdomains.size();
    CHECK(subdomains == whole.subdomain_count());
    check_figures_combine(whole, parts);
  }
}

TEST_CASE("join_parts: parts not of one run are refused") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/key.poly");
  const madd::MeshOptions o = madd::test::options_for(6, 30, madd::domain_area(domain) / 500);
  int rounds = 0;
  std::vector<madd::MeshPart> parts = mesh_in_shares(domain, o, 3, rounds);
  CHECK_THROWS_AS(madd::join_parts(std::vector<madd::MeshPart>(parts.begin(), parts.begin() + 2)),
                  madd::InvalidInputError);
  CHECK_THROWS_AS(madd::join_parts(std::vector<madd::MeshPart>{parts[0], parts[0], parts[1]}), madd::InvalidInputError);
  parts[1].triangle_ids.front() = parts[1].total_triangles;
  CHECK_THROWS_AS(madd::join_parts(parts), madd::InvalidInputError);
  CHECK_THROWS_AS(madd::join_parts(std::vector<madd::MeshPart>{}), madd::InvalidInputError);
}

TEST_CASE("mesh_share: separator pieces split between rounds are agreed on by every share (the archipelago at q 33)") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/archipelago.poly");
  const madd::MeshOptions o = madd::test::options_for(12, 33, madd::domain_area(domain) / 20000);
  const madd::Mesh whole = madd::mesh(domain, o);
  int rounds = 0;
  const std::vector<madd::MeshPart> parts = mesh_in_shares(domain, o, 3, rounds);
  CHECK(rounds > 0);  // the case this test is for: a split agreed between rounds
  check_union_is(whole, parts);
}

TEST_CASE("refine_in_rounds: each subdomain's mesh is checked on its thread once final, and only then") {
  // The archipelago at q 33 has separator pieces split between rounds (the
  // test above): a subdomain meshed again in a later round must be checked
  // in that round, on the mesh it keeps, and a mesh that stopped a fix only
  // when the rounds have run out.
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/archipelago.poly");
  madd::MeshOptions o = madd::test::options_for(12, 33, madd::domain_area(domain) / 20000);
  o.decomposition.threads = 2;
  const madd::detail::AreaBound field(o.size, &domain);
  const madd::Decomposition before = madd::decompose_for_mesh(domain, o).decomposition;
  const madd::detail::ResourceGuard guard({0.0, 0, static_cast<std::uint32_t>(before.subdomains.size())});
  const madd::detail::RegionView view = madd::detail::region_view(before);
  madd::Decomposition d = madd::detail::discretise(before, field, false, &guard, 2, &view);
  const std::vector<double> work =
      madd::detail::expected_triangles(d, madd::detail::DomainWork(domain, field), 2, &before, &view);
  const std::size_t n = d.subdomains.size();
  std::mutex m;
  std::vector<int> checks(n, 0);
  std::vector<std::size_t> last_checked(n, 0);
  std::vector<int> blocked_at(n, 0);  // 1 + the check of k whose mesh still stopped a fix

  const madd::detail::SubdomainCheck check = [&](std::uint32_t k, const madd::detail::LocalDomain&,
                                                 const madd::detail::SubdomainMesh& piece) {
    const std::lock_guard lock(m);
    ++checks[k];
    last_checked[k] = piece.triangles.size();
    if (!piece.blocking_separators.empty()) blocked_at[k] = checks[k];
  };
  madd::MeshReport report;
  std::vector<madd::detail::SubdomainMesh> pieces;
  const auto alone = [](const std::vector<std::uint32_t>& mine) { return mine; };
  madd::detail::refine_in_rounds(d, o, field, work, guard, std::vector<bool>(n, true), alone, report, pieces,
                                 view.regions, check);
  int again = 0;
  for (std::size_t k = 0; k < n; ++k) {
    CHECK(checks[k] >= 1);
    CHECK(last_checked[k] == pieces[k].triangles.size());
    again += checks[k] > 1 ? 1 : 0;
  }
  // A mesh that stopped a fix is checked only when no round follows (the
  // rounds ran out): its check is the subdomain's last, on the mesh it keeps.
  for (std::size_t k = 0; k < n; ++k)
    if (blocked_at[k] != 0) {
      CHECK(blocked_at[k] == checks[k]);
      CHECK(!pieces[k].blocking_separators.empty());
    }
  CHECK(again > 0);  // the case this test is for: meshed again, checked again
}

TEST_CASE("mesh_share: with interior segments, isolated vertices and regions, 1 and 2 shares make mesh()'s mesh") {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  madd::MeshOptions o = madd::test::options_for(2, 30, 0.01);
  const madd::Mesh whole = madd::mesh_decomposition(f.decomposition, f.domain, o).mesh;
  REQUIRE(!whole.triangle_attribute.empty());
  for (const std::uint32_t shares : {1u, 2u}) {
    CAPTURE(shares);
    int rounds = 0;
    const std::vector<madd::MeshPart> parts =
        mesh_decomposition_in_shares(f.decomposition, f.domain, o, shares, rounds);
    check_union_is(whole, parts);
    check_owners(parts);
    // The isolated vertices are in the part of the share meshing subdomain 1, under their own ids.
    for (const madd::MeshPart& part : parts) {
      // The part's .ele: a third attribute, the region attribute of each triangle.
      std::istringstream ele(madd::format_part_ele(part));
      std::size_t count = 0, corners = 0, attributes = 0;
      ele >> count >> corners >> attributes;
      CHECK(count == part.mesh.triangles.size());
      CHECK(attributes == 3);
      for (std::size_t t = 0; t < count; ++t) {
        double id = 0, a = 0, b = 0, c = 0, k = 0, global = 0, region = 0;
        ele >> id >> a >> b >> c >> k >> global >> region;
        CHECK(region == whole.triangle_attribute[part.triangle_ids[t]]);
      }
      CHECK(madd::format_parts_pvtu({"p-0.vtu"}, true).find("Name=\"region_attribute\"") != std::string::npos);
      const bool has_one = part.owner[1] == part.share;
      for (const std::uint64_t v : {15u, 16u})
        CHECK(has_one == (std::find(part.point_ids.begin(), part.point_ids.end(), v) != part.point_ids.end()));
    }
  }
}

TEST_CASE("mesh_share: 2 and 3 shares of the estuary (interior segments, survey points, a region) make mesh()'s mesh") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/estuary.poly");
  madd::MeshOptions o = madd::test::options_for(6, 30, 0.05);
  const madd::Mesh whole = madd::mesh(domain, o);
  for (const std::uint32_t shares : {2u, 3u}) {
    CAPTURE(shares);
    int rounds = 0;
    const std::vector<madd::MeshPart> parts = mesh_in_shares(domain, o, shares, rounds);
    check_union_is(whole, parts);
    check_owners(parts);
  }
}

TEST_CASE("assign_shares: every share gets work, none more than the largest subdomain above the mean") {
  const std::vector<double> work{5, 1, 9, 3, 3, 7, 2, 8, 4, 6};
  for (std::uint32_t shares = 1; shares <= 4; ++shares) {
    const std::vector<std::uint32_t> owner = madd::assign_shares(work, shares);
    std::vector<double> load(shares, 0);
    for (std::size_t k = 0; k < work.size(); ++k) {
      REQUIRE(owner[k] < shares);
      load[owner[k]] += work[k];
    }
    const double mean = 48.0 / shares;
    for (const double l : load) {
      CHECK(l > 0);
      CHECK(l <= mean + 9);  // greedy: a share is only ever given work while it is the least loaded
    }
  }
  CHECK_THROWS_AS(madd::mesh_share({}, {}, {}, 2, 2, {}), madd::OptionError);
}

TEST_CASE("mesh part files: the .node carries each vertex's global id and owner, the .vtu its GlobalIds, the .pvtu "
          "every piece") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/key.poly");
  const madd::MeshOptions o = madd::test::options_for(4, 30, madd::domain_area(domain) / 500);
  int rounds = 0;
  const std::vector<madd::MeshPart> parts = mesh_in_shares(domain, o, 2, rounds);
  const madd::MeshPart& p = parts[1];
  // .node: a header, then "id x y global owner marker" with global + 1 and the owner.
  std::istringstream node(madd::format_part_node(p, 1));
  std::size_t n = 0, dim = 0, attributes = 0, markers = 0;
  node >> n >> dim >> attributes >> markers;
  CHECK(n == p.mesh.points.size());
  CHECK(attributes == 2);
  for (std::size_t v = 0; v < n; ++v) {
    std::size_t id = 0, global = 0, owner = 0;
    double x = 0, y = 0;
    int marker = 0;
    node >> id >> x >> y >> global >> owner >> marker;
    REQUIRE(id == v + 1);
    CHECK(global == p.point_ids[v] + 1);
    CHECK(owner == p.point_owner[v]);
  }
  // .vtu: the 0-based global ids of every point, in order, declared as GlobalIds.
  const std::string vtu = madd::format_part_vtu(p);
  CHECK(vtu.find("GlobalIds=\"global_id\"") != std::string::npos);
  const std::size_t at = vtu.find("Name=\"global_id\" IdType=\"1\"");
  REQUIRE(at != std::string::npos);
  std::istringstream ids(vtu.substr(vtu.find('\n', at) + 1));
  for (std::size_t v = 0; v < n; ++v) {
    std::uint64_t g = 0;
    ids >> g;
    REQUIRE(g == p.point_ids[v]);
  }
  const std::string pvtu = madd::format_parts_pvtu({"m-0.vtu", "m-1.vtu"});
  CHECK(pvtu.find("<Piece Source=\"m-0.vtu\"/>") != std::string::npos);
  CHECK(pvtu.find("<Piece Source=\"m-1.vtu\"/>") != std::string::npos);
}
