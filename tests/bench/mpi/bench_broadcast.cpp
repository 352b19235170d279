// Every rank decomposing the domain itself, or rank 0 decomposing it and
// broadcasting it (issue 15; docs/mpi.md, "One decomposition, every rank"):
// which gets the decomposition to every rank sooner. Prints the medians of
// REPEAT runs of both, on the ranks mpirun gives.
//   mpirun -np P bench_mpi_broadcast DOMAIN.poly N AREA [REPEAT]
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <type_traits>
#include <vector>

#include "madd/mesh_share.hpp"
#include "madd/poly_io.hpp"

namespace {

// The decomposition as bytes and back: what a broadcast would carry.
struct Bytes {
  std::vector<char> data;
  std::size_t at = 0;

  template <typename T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const char* p = reinterpret_cast<const char*>(&v);
    data.insert(data.end(), p, p + sizeof v);
  }
  template <typename T>
  void put(const std::vector<T>& v) {
    put(v.size());
    if constexpr (std::is_trivially_copyable_v<T>) {
      const char* p = reinterpret_cast<const char*>(v.data());
      data.insert(data.end(), p, p + sizeof(T) * v.size());
    } else {
      for (const T& x : v) put(x);
    }
  }
  template <typename T>
  void get(T& v) {
    std::memcpy(&v, data.data() + at, sizeof v);
    at += sizeof v;
  }
  template <typename T>
  void get(std::vector<T>& v) {
    std::size_t n = 0;
    get(n);
    v.resize(n);
    if constexpr (std::is_trivially_copyable_v<T>) {
      std::memcpy(static_cast<void*>(v.data()), data.data() + at, sizeof(T) * n);
      at += sizeof(T) * n;
    } else {
      for (T& x : v) get(x);
    }
  }
};

void put_all(Bytes& b, const madd::Decomposition& d) {
  b.put(d.points), b.put(d.segments), b.put(d.segment_origin), b.put(d.holes);
  b.put(d.subdomains.size());
  for (const madd::Subdomain& s : d.subdomains) {
    b.put(s.rings), b.put(s.ring_segments), b.put(s.area), b.put(s.weight), b.put(s.required_area);
    b.put(s.interior_point), b.put(s.hole_points);
  }
  b.put(d.separator_angle_deg), b.put(d.subdomain_area_ratio);
}

void get_all(Bytes& b, madd::Decomposition& d) {
  b.get(d.points), b.get(d.segments), b.get(d.segment_origin), b.get(d.holes);
  std::size_t n = 0;
  b.get(n);
  d.subdomains.resize(n);
  for (madd::Subdomain& s : d.subdomains) {
    b.get(s.rings), b.get(s.ring_segments), b.get(s.area), b.get(s.weight), b.get(s.required_area);
    b.get(s.interior_point), b.get(s.hole_points);
  }
  b.get(d.separator_angle_deg), b.get(d.subdomain_area_ratio);
}

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// Seconds from a common start until the last rank has the decomposition.
double until_everyone(double start) {
  const double mine = now() - start;
  double last = 0;
  MPI_Allreduce(&mine, &last, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return last;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc < 4) {
    if (rank == 0) std::fprintf(stderr, "usage: mpirun -np P bench_mpi_broadcast DOMAIN.poly N AREA [REPEAT]\n");
    MPI_Finalize();
    return 2;
  }
  const madd::Pslg domain = madd::read_domain(argv[1]);
  madd::MeshOptions o;
  o.decomposition.subdomains = static_cast<std::uint32_t>(std::atoi(argv[2]));
  o.decomposition.threads = 1;
  o.size.max_triangle_area = std::atof(argv[3]);
  const int repeat = argc > 4 ? std::atoi(argv[4]) : 3;
  std::vector<double> every, root, bytes_seconds;
  std::size_t bytes = 0;
  bool same = true;
  for (int i = 0; i < repeat; ++i) {
    MPI_Barrier(MPI_COMM_WORLD);
    double start = now();
    const madd::Decomposition mine = madd::decompose_for_mesh(domain, o).decomposition;
    every.push_back(until_everyone(start));

    MPI_Barrier(MPI_COMM_WORLD);
    start = now();
    Bytes b;
    if (rank == 0) put_all(b, madd::decompose_for_mesh(domain, o).decomposition);
    std::size_t n = b.data.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    b.data.resize(n);
    const double send = now();
    MPI_Bcast(b.data.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
    madd::Decomposition received;
    get_all(b, received);
    bytes_seconds.push_back(until_everyone(send));
    root.push_back(until_everyone(start));
    bytes = n;
    same = same && received == mine;  // the decomposition is the same everywhere either way
  }
  if (rank == 0)
    std::printf("%s, N = %s, %d ranks, %d runs (medians): every rank decomposes %.3f s; rank 0 decomposes and "
                "broadcasts %.3f s (%zu bytes, %.3f s to send and unpack); identical: %s\n",
                argv[1], argv[2], size, repeat, median(every), median(root), bytes, median(bytes_seconds),
                same ? "yes" : "NO");
  MPI_Finalize();
  return same ? 0 : 1;
}
