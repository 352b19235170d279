#!/bin/sh
# Passes when the program $1 is statically linked (MADD_STATIC_CLI): ldd says
# "not a dynamic executable" (or "statically linked" for static-pie), or
# file(1) says "statically linked".
set -u
out=$(ldd "$1" 2>&1)
case "$out" in
  *"not a dynamic executable"* | *"statically linked"*) echo "static: $1"; exit 0 ;;
esac
if command -v file > /dev/null 2>&1; then
  case "$(file -L "$1")" in
    *"statically linked"*) echo "static: $1"; exit 0 ;;
  esac
fi
echo "check_static.sh: $1 is dynamically linked:" >&2
echo "$out" >&2
exit 1
