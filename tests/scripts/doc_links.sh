#!/usr/bin/env bash
# No file of the repository cites a document or path that is not in the repository: every
# relative Markdown link resolves (from the linking file's folder), every path a file names
# under one of the repository's top folders exists (from the repository root), no file
# points at the notes kept outside it (shared/, ../shared) or at an issue tracker's
# numbers, and every NAME.md a file names exists somewhere in the repository. A citation
# that cannot resolve tells a reader nothing, and goes stale without anyone noticing.
# Paths with placeholders (NAME, TARGET, $var, *, <...>) are templates, not citations.
# Usage: bash doc_links.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
cd "$src" || exit 1

# The files to read: what git tracks (a fresh clone), else every file but build outputs.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git ls-files -z --cached --others --exclude-standard >"$tmp/files"
else
  find . -type f -not -path './build*' -not -path './.git/*' -printf '%P\0' >"$tmp/files"
fi
# Text files only (grep -I skips binary ones); this script itself names the patterns.
xargs -0 grep -IlZ '' <"$tmp/files" 2>/dev/null | tr '\0' '\n' |
  grep -v -e '^tests/scripts/doc_links.sh$' >"$tmp/text"
[ -s "$tmp/text" ] || { echo "FAIL: no text files found under $src" >&2; exit 1; }

top='(docs|tests|examples|bench|scripts|fuzz|cli|lang|povray|primitives|render|scenegraph|csg|images)'
placeholder='(NAME|TARGET|FORMAT|[$*<>{}]|\.\.\.)'
checked=0

# 1. Relative Markdown links [text](target) in .md files.
while IFS= read -r file; do
  dir=$(dirname "$file")
  while IFS= read -r target; do
    target=${target%%#*}
    [ -z "$target" ] && continue
    checked=$((checked + 1))
    [ -e "$dir/$target" ] || fail "$file links to '$target', which does not exist"
  done < <(grep -oE '\]\([^) ]+\)' "$file" | sed 's/^](//; s/)$//' |
             grep -vE '^(https?:|mailto:|#)' | grep -vE "$placeholder")
done < <(grep -E '\.md$' "$tmp/text")

# 2. Paths under the repository's top folders, in any text file: from the repository root
# or the file's own folder (docs/ names its images/ so), a file or a program built from one
# (bench/bvh_build for bench/bvh_build.cpp, scenegraph/transform_syntax for its .h/.cpp).
exists() {  # exists PATH DIR
  local p
  for p in "$1" "$2/$1"; do
    [ -e "$p" ] && return 0
    compgen -G "$p.*" >/dev/null && return 0
  done
  return 1
}
while IFS= read -r file; do
  dir=$(dirname "$file")
  while IFS= read -r path; do
    path=${path%.}
    checked=$((checked + 1))
    exists "$path" "$dir" || fail "$file names '$path', which does not exist"
  done < <(grep -oE "(^|[^A-Za-z0-9_./-])$top/[A-Za-z0-9_./+*\$<>{}-]*" "$file" |
             sed -E 's/^[^a-z]//' | grep -vE "$placeholder" | sed -E 's/[.,:;-]+$//' | sort -u)
done <"$tmp/text"

# 3. Notes outside the repository, and issue numbers.
# report FILE WHAT: each line of FILE is a failure.
report() {
  [ -s "$1" ] || return 0
  sed "s/^/FAIL: $2: /" "$1" >&2
  failures=$((failures + $(wc -l <"$1")))
}
tr '\n' '\0' <"$tmp/text" | xargs -0 grep -nE '(^|[^A-Za-z0-9_])(\.\./)*shared/[A-Za-z0-9_-]+\.md' \
  >"$tmp/shared" 2>/dev/null
report "$tmp/shared" "cites notes outside the repository"
tr '\n' '\0' <"$tmp/text" | xargs -0 grep -nE '\b[Ii]ssues? #?[0-9]+' >"$tmp/issues" 2>/dev/null
report "$tmp/issues" "cites an issue number (say what is required instead)"

# 4. Any NAME.md named in a text file exists somewhere in the repository.
sed 's|.*/||' "$tmp/text" | grep -E '\.md$' | sort -u >"$tmp/md_names"
while IFS= read -r file; do
  while IFS= read -r name; do
    checked=$((checked + 1))
    grep -qxF "$name" "$tmp/md_names" || fail "$file names '$name', which is not in the repository"
  done < <(grep -oE '(^|[^A-Za-z0-9_./-])[A-Za-z0-9_-]+\.md\b' "$file" | sed -E 's/^[^A-Za-z0-9_]//' |
             grep -vE "^$placeholder" | sort -u)
done <"$tmp/text"

[ "$checked" -gt 100 ] || fail "only $checked citations found: the patterns no longer match"
if [ "$failures" -eq 0 ]; then
  echo "doc_links: OK: $checked citations resolve"
  exit 0
fi
echo "doc_links: FAIL: $failures citation(s) lead nowhere" >&2
exit 1
