#!/bin/sh
# The C++ sources keep the style of .clang-format: clang-format changes
# nothing in src/ include/ cli/ tests/ fuzz/ (seed corpora aside). Run by
# ctest when clang-format 14 (Debian 12's, what the style was applied with)
# is found; other versions format a few constructs differently, so they are
# not asked. To apply the style:  clang-format -i $(tests/check_format.sh --list)
# Usage: tests/check_format.sh [--list | CLANG_FORMAT]
set -eu
cd "$(dirname "$0")/.."
files=$(find src include cli tests fuzz -path fuzz/corpus -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print | sort)
if [ "${1:-}" = "--list" ]; then echo "$files"; exit 0; fi
tool=${1:-clang-format}
# shellcheck disable=SC2086
"$tool" --dry-run --Werror $files
