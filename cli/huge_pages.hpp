#pragma once
// Malloc's heaps on transparent huge pages, for the command-line programs.
//
// A large mesh touches every page of its arrays once: the subdomains'
// refinement meshes, the merged mesh, the check's flags. With 4 KiB pages
// the kernel takes a fault and zeroes a page each time, about 8 us a page on
// the development machine: system time was a quarter of a whole `madd mesh`
// run at 1.5 M triangles and nearly half at 4 x 10^7 (docs/performance.md,
// "Huge pages").
// glibc can put its heaps on 2 MiB pages (the tunable glibc.malloc.hugetlb=1,
// glibc 2.35 and later, where the kernel's transparent huge pages are set to
// `madvise`). And a run frees and allocates again many arrays of tens of
// megabytes (each subdomain's mesh, the check's flags, the files' pieces):
// glibc gives the top of a heap back to the kernel as soon as it is free and
// takes fresh, zeroed pages the next time, unless the heap keeps some slack
// (glibc.malloc.top_pad, `heap_slack` below): 64 MiB of it cut a
// 1.5 M-triangle run by a sixth on two threads and a 10^7 one by a tenth
// ("Huge pages" again). Setting it stops glibc from raising its mmap
// threshold as large blocks are freed (from 128 KiB up to 32 MiB), so every
// block above 128 KiB would be a fresh mapping, zeroed: each subdomain's
// arrays at 2 x 10^8 triangles (refinement 76.7 -> 90.8 s); so the threshold
// is set to that ceiling too (`mmap_threshold` below; 2 x 10^8 triangles in
// 111 s instead of 142). glibc reads its tunables only when a process starts,
// so the programs' main() calls restart_with_huge_pages() first: it sets
// them and executes the same program again, once, with the same arguments.
#include <optional>
#include <string>

namespace madd::cli {

// The heap's slack, glibc.malloc.top_pad's value: 64 MiB.
inline constexpr const char* heap_slack = "67108864";
// Blocks from this size on are mappings of their own (glibc.malloc.mmap_threshold): 32 MiB.
inline constexpr const char* mmap_threshold = "33554432";

// What GLIBC_TUNABLES should become (the caller's tunables, if any, then
// glibc.malloc.hugetlb=1, glibc.malloc.top_pad=heap_slack and
// glibc.malloc.mmap_threshold=mmap_threshold, each unless the tunables name
// it already: the user's choice, or this program started again), or nothing
// to do: when none is to be added, when `opt_out` (the
// variable MADD_HUGE_PAGES) is "0", or when `ld_preload` names a tool that
// wraps the program (valgrind's preloads: an exec would leave the tool). The
// huge pages only where `thp_enabled` (the text of
// /sys/kernel/mm/transparent_hugepage/enabled, null when unreadable) selects
// [madvise] ([always] needs no advice, [never] takes none); the others always.
std::optional<std::string> tunables_for_huge_pages(const char* tunables, const char* opt_out, const char* ld_preload,
                                                   const char* thp_enabled);

// Executes the running program again with the tunables above when there is
// something to do and the C library is glibc 2.35 or later; returns (and the
// program goes on as it is) when not, or when the exec fails. Call it first
// in main(), before anything is read, written or started.
void restart_with_huge_pages(char** argv);

}  // namespace madd::cli
