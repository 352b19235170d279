#!/bin/sh
# madd-mpi's parts, joined by their global ids, are `madd mesh`'s mesh for the
# same options: vertex for vertex (the same coordinate text, the same
# marker) and triangle for triangle (the same global id, the same vertices in
# the same order, the same subdomain), at NP ranks; the .pvtu names every
# rank's .vtu. Run by ctest (tests/CMakeLists.txt) as
#   union_test.sh MPIEXEC NP MADD MADD_MPI DOMAIN WORKDIR [mesh options...]
set -eu
mpiexec=$1 np=$2 madd=$3 madd_mpi=$4 domain=$5 work=$6
shift 6
rm -rf "$work" && mkdir -p "$work/one" "$work/parts"
"$madd" mesh "$domain" -j 1 --quiet -o "$work/one/m" --report="$work/one/r.json" "$@"
# Root in a container or CI runner: Open MPI refuses root without this flag.
root_flag=""
[ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
"$mpiexec" $root_flag --oversubscribe -np "$np" "$madd_mpi" mesh "$domain" -j 1 --quiet --vtu -o "$work/parts/m" \
  --report="$work/parts/r.json" "$@"

fail() { echo "union_test: $*" >&2; exit 1; }
last=$((np - 1))
for r in $(seq 0 "$last"); do
  for ext in node ele vtu; do [ -f "$work/parts/m-$r.$ext" ] || fail "rank $r wrote no m-$r.$ext"; done
  grep -q "<Piece Source=\"m-$r.vtu\"/>" "$work/parts/m.pvtu" || fail "m.pvtu does not name m-$r.vtu"
done
[ "$(grep -c '<Piece ' "$work/parts/m.pvtu")" = "$np" ] || fail "m.pvtu names other than $np pieces"

# The whole mesh, without headers or comments: "id x y marker", "id a b c k".
tail -n +2 "$work/one/m.node" | grep -v '^#' | sort > "$work/one.node"
tail -n +2 "$work/one/m.ele" | grep -v '^#' | sort > "$work/one.ele"
# The parts in the same form: a vertex as "global x y marker" (once, though
# several ranks have it), a triangle as "global ga gb gc k".
: > "$work/parts.node.all"
: > "$work/parts.ele.all"
for r in $(seq 0 "$last"); do
  awk 'NR > 1 && !/^#/ { print $4, $2, $3, $6 }' "$work/parts/m-$r.node" >> "$work/parts.node.all"
  awk 'FNR == NR { if (FNR > 1 && !/^#/) id[$1] = $4; next }
       FNR > 1 && !/^#/ { print $6, id[$2], id[$3], id[$4], $5 }' \
    "$work/parts/m-$r.node" "$work/parts/m-$r.ele" >> "$work/parts.ele.all"
done
sort -u "$work/parts.node.all" > "$work/parts.node"
sort "$work/parts.ele.all" > "$work/parts.ele"
cmp -s "$work/one.node" "$work/parts.node" || fail "the parts' vertices differ from madd mesh's ($(diff "$work/one.node" "$work/parts.node" | head -3))"
cmp -s "$work/one.ele" "$work/parts.ele" || fail "the parts' triangles differ from madd mesh's ($(diff "$work/one.ele" "$work/parts.ele" | head -3))"
# Each vertex has one owner, the same in every part that has it.
owners=$(for r in $(seq 0 "$last"); do awk 'NR > 1 && !/^#/ { print $4, $5 }' "$work/parts/m-$r.node"; done | sort -u | awk '{ print $1 }' | uniq -d | wc -l)
[ "$owners" = 0 ] || fail "$owners vertices have different owners in different parts"
# The reports give the same work estimate and the same actual count of every
# subdomain (the MPI driver sums its ranks' parts).
for key in subdomain_predicted_triangles subdomain_triangles predicted_triangles; do
  one=$(grep "\"$key\":" "$work/one/r.json") || fail "madd mesh's report has no $key"
  parts=$(grep "\"$key\":" "$work/parts/r.json") || fail "madd-mpi's report has no $key"
  [ "$one" = "$parts" ] || fail "$key differs: madd mesh $one, madd-mpi $parts"
done
echo "union_test: $np ranks: $(wc -l < "$work/one.ele") triangles, $(wc -l < "$work/one.node") vertices, identical to madd mesh"
