#!/usr/bin/env bash
# The parser is stricter than docs/lucent.xsd, so every shipped example must also pass
# `lucent check` cleanly: exit status 0 and no warning. Covers examples/*.xml (the files
# in examples/parts/ are checked through examples/include.xml, which includes them), the
# parameter overrides that examples/params.xml documents, and the complete scenes (those
# with a <camera>) among the xml examples of docs/scene-language.md.
# Run by CTest as: bash schema_examples_check.sh <lucent-binary> <source-dir>
set -u

lucent=${1:?usage: schema_examples_check.sh <lucent-binary> <source-dir>}
src=${2:?usage: schema_examples_check.sh <lucent-binary> <source-dir>}

failures=0
checked=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# check NAME FILE [ARGS...]: lucent check must exit 0 and print no warning or error.
check() {
  local name=$1 file=$2
  shift 2
  "$lucent" check "$file" "$@" >"$work/out" 2>"$work/err"
  local status=$?
  checked=$((checked + 1))
  if [ $status -ne 0 ]; then
    cat "$work/err"
    echo "FAILED (lucent check exit status $status): $name"
    failures=$((failures + 1))
  elif grep -q -e 'warning:' -e 'error:' "$work/err"; then
    cat "$work/err"
    echo "NOT CLEAN (warnings): $name"
    failures=$((failures + 1))
  fi
}

examples=$(find "$src/examples" -maxdepth 1 -name '*.xml' -type f | sort)
if [ -z "$examples" ]; then
  echo "schema_examples_check: FAIL: no examples/*.xml found"
  exit 1
fi
for f in $examples; do
  check "${f#$src/}" "$f"
done

# The overrides examples/params.xml shows in its header comment.
check "examples/params.xml -D radius=1.4 -D hue=..." "$src/examples/params.xml" \
  -D radius=1.4 -D "hue=0.2 0.5 0.9"
check "examples/params.xml -D turn=60 -D glass_ior=1.1" "$src/examples/params.xml" \
  -D turn=60 -D glass_ior=1.1

# Complete scenes among the reference's xml examples (same extraction as schema_validate.sh).
awk -v dir="$work" '
  /^ *```xml *$/ { n++; inb = 1; f = sprintf("%s/block%02d.xml", dir, n); printf "" > f; next }
  /^ *``` *$/ && inb { inb = 0; close(f); next }
  inb { sub(/^  /, ""); print > f }' "$src/docs/scene-language.md"
doc_scenes=0
for f in "$work"/block*.xml; do
  [ -e "$f" ] || continue
  grep -q '<scene' "$f" && grep -q '<camera' "$f" || continue
  doc_scenes=$((doc_scenes + 1))
  check "xml example $(basename "$f" .xml) of docs/scene-language.md" "$f"
done
if [ $doc_scenes -lt 1 ]; then
  echo "no complete scene found among the xml examples of docs/scene-language.md"
  failures=$((failures + 1))
fi

if [ $failures -eq 0 ]; then
  echo "schema_examples_check: OK: $checked checks passed ($doc_scenes scenes from the reference)"
  exit 0
fi
echo "schema_examples_check: FAIL: $failures of $checked checks failed"
exit 1
