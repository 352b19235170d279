#pragma once
// Large arrays filled on several threads: their pages faulted in on those
// threads too.
//
// The kernel zeroes a fresh page when it is first touched, and takes a page
// fault to do it. vector::resize touches every page of a new array on the
// calling thread, so a merged mesh of 10^7 triangles (about 400 MB) took all
// its faults on one thread: a fifth of `madd mesh`'s whole run there, and
// most of what did not speed up with a second thread (docs/performance.md,
// "Fresh memory"). resize_on_threads() reserves the array, has `threads`
// threads fault in a share of its new pages each (madvise MADV_POPULATE_WRITE,
// Linux 5.14 and later; elsewhere nothing is done and resize faults them in
// as before), then resizes it: the value-initialising pass then runs over
// pages already there.
#include <cstddef>
#include <vector>

namespace madd::detail {

// Faults in the pages of [data, data + bytes) for writing, in shares on
// `threads` threads (0: one per core). Only a hint: does nothing where the
// system cannot, or for fewer than a few megabytes.
void fault_in_on_threads(void* data, std::size_t bytes, unsigned threads);

// Gives the heap's free pages back to the system (glibc's malloc_trim;
// elsewhere nothing). For a phase that frees many small arrays and then
// allocates a few large ones: the heap cannot put those into the scattered
// free space, so their fresh pages would add to resident memory that is no
// longer used (madd-mpi's part of a mesh, src/mesh/mesh_share.cpp).
void release_free_memory();

// v.resize(n), its new pages faulted in on `threads` threads first.
template <typename T, typename Allocator>
void resize_on_threads(std::vector<T, Allocator>& v, std::size_t n, unsigned threads) {
  if (n > v.size()) {
    v.reserve(n);
    fault_in_on_threads(v.data() + v.size(), (n - v.size()) * sizeof(T), threads);
  }
  v.resize(n);
}

// v.assign(n, value), the same way.
template <typename T, typename Allocator>
void assign_on_threads(std::vector<T, Allocator>& v, std::size_t n, const T& value, unsigned threads) {
  v.clear();
  v.reserve(n);
  fault_in_on_threads(v.data(), n * sizeof(T), threads);
  v.assign(n, value);
}

}  // namespace madd::detail
