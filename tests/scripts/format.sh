#!/usr/bin/env bash
# The house style is kept by a tool: every C++ file of the tree (outside build folders and
# test data) is as clang-format leaves it under .clang-format. A file it would change fails,
# with the first lines of the change; `clang-format -i FILE` applies it.
# Run by CTest as: bash format.sh <lucent-binary> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
command -v clang-format >/dev/null || { echo "FAIL: clang-format is not installed (scripts/install-deps installs it)"; exit 1; }
[ -f "$src/.clang-format" ] || { echo "FAIL: $src/.clang-format is missing"; exit 1; }

count=0
while IFS= read -r -d '' f; do
  count=$((count + 1))
  if ! clang-format --style=file "$f" | diff -u "$f" - >"$tmp/diff"; then
    fail "${f#"$src"/} is not formatted (clang-format -i ${f#"$src"/}):"
    head -20 "$tmp/diff" >&2
  fi
done < <(find "$src" \( -path "$src/build*" -o -path "$src/.git" -o -path "$src/tests/data" \) -prune \
              -o \( -name '*.cpp' -o -name '*.h' \) -type f -print0)

# The check itself: an unformatted line is found.
printf 'int  main( ) {return 0;}\n' >"$tmp/bad.cpp"
cp "$src/.clang-format" "$tmp/"
if clang-format --style=file "$tmp/bad.cpp" | diff -q "$tmp/bad.cpp" - >/dev/null; then
  fail "clang-format accepted an unformatted file"
fi

[ "$count" -gt 100 ] || fail "only $count C++ files found under $src"
[ "$failures" -eq 0 ] && echo "format: $count files as clang-format leaves them"
exit $((failures > 0))
