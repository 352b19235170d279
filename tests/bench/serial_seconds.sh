#!/bin/sh
# The serial fraction of one run, measured directly rather than fitted:
# `perf record` samples the whole process at 5 kHz on every CPU it runs on,
# and in each 10 ms window of the run the CPUs not busy with it are counted.
# At -j J, a window with only one thread's work idles J - 1 CPUs; the idle
# CPU-seconds over J - 1 are the serial seconds s of Amdahl's model, and
# s over the busy CPU-seconds (the one-thread time, less what threads add)
# is the serial fraction f. Each run follows an untimed twin (cold memory:
# docs/performance.md). CLEAN="GLOB" removes the files matching GLOB before
# each timed run (replacing a file frees the old one's pages in rename, on
# one thread: a cost of the file system, which a first run does not pay).
#   tests/bench/serial_seconds.sh J K -- COMMAND...   (K runs; needs perf)
# for example
#   tests/bench/serial_seconds.sh 2 5 -- build/madd mesh data/pipe.poly -n 64 -q 30 -a 0.00025 -j 2 -o /tmp/m
set -eu
threads=$1 runs=$2
shift 2
[ "$1" = "--" ] && shift
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for i in $(seq "$runs"); do
  "$@" >/dev/null
  # shellcheck disable=SC2086
  [ -n "${CLEAN:-}" ] && rm -f $CLEAN
  perf record -q -F 5000 -o "$scratch/p.data" -- "$@" >/dev/null 2>&1
  perf script -i "$scratch/p.data" -F time 2>/dev/null >"$scratch/t$i"
done
python3 - "$threads" "$scratch" "$runs" <<'PY'
import collections, statistics, sys
threads, scratch, runs = int(sys.argv[1]), sys.argv[2], int(sys.argv[3])
per, window = 50, 0.01  # samples a busy CPU gives a 10 ms window at 5 kHz
fractions = []
for i in range(1, runs + 1):
    times = [float(l.strip().rstrip(':')) for l in open('%s/t%d' % (scratch, i)) if l.strip()]
    t0 = times[0]
    count = collections.Counter(int((t - t0) / window) for t in times)
    windows = int((times[-1] - t0) / window)
    idle = sum(max(0, threads * per - count[k]) for k in range(windows)) / per * window
    busy = len(times) / per * window
    s = idle / (threads - 1)
    fractions.append(s / busy)
    print('run %d: %.3f s long, busy %.3f CPU-s, serial %.3f s: f = %.1f%%' % (i, times[-1] - t0, busy, s, 100 * s / busy))
f = statistics.median(fractions)
print('median serial fraction %.1f%%; Amdahl predicts %s' % (100 * f, ', '.join(
    '%.1fx on %d cores' % (1 / (f + (1 - f) / c), c) for c in (2, 4, 16, 64))))
PY
