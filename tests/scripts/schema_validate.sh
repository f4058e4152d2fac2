#!/usr/bin/env bash
# docs/lucent.xsd must accept every scene we ship or test as valid (examples/**/*.xml,
# tests/lang/valid/*.xml, the xml examples of docs/scene-language.md) and reject every scene
# of the bad-scene corpus that tests/bad/cases.txt marks with an "xmllint" line.
# Run by CTest as: bash schema_validate.sh <lucent-binary> <source-dir>
set -u

src=${2:?usage: schema_validate.sh <lucent-binary> <source-dir>}
xsd="$src/docs/lucent.xsd"

if ! command -v xmllint >/dev/null; then
  echo "schema_validate: FAIL: xmllint not found (Debian package libxml2-utils)"
  exit 1
fi
# A schema that does not compile would make every bad file "rejected".
if ! out=$(xmllint --noout "$xsd" 2>&1); then
  echo "$out"
  echo "schema_validate: FAIL: $xsd is not well-formed"
  exit 1
fi

failures=0
accepted=0
rejected=0

# xmllint exit status: 0 valid, 3 or 4 invalid, 5 schema compilation error, 1 not well-formed.
valid_files=$(
  { find "$src/examples" -name '*.xml' -type f 2>/dev/null
    [ -d "$src/tests/lang/valid" ] && find "$src/tests/lang/valid" -name '*.xml' -type f
  } | sort)
for f in $valid_files; do
  if out=$(xmllint --noout --schema "$xsd" "$f" 2>&1); then
    accepted=$((accepted + 1))
  else
    echo "$out"
    echo "REJECTED (should be valid): ${f#$src/}"
    failures=$((failures + 1))
  fi
done

# Every ```xml block of the language reference: a whole <scene> as it is, a fragment wrapped
# in <scene version="1">, so the examples users copy are valid.
doc="$src/docs/scene-language.md"
blocks=$(mktemp -d)
trap 'rm -rf "$blocks"' EXIT
awk -v dir="$blocks" '
  /^ *```xml *$/ { n++; inb = 1; f = sprintf("%s/block%02d.xml", dir, n); printf "" > f; next }
  /^ *``` *$/ && inb { inb = 0; close(f); next }
  inb { sub(/^  /, ""); print > f }' "$doc"
doc_blocks=0
for f in "$blocks"/block*.xml; do
  [ -e "$f" ] || continue
  doc_blocks=$((doc_blocks + 1))
  if ! grep -q '<scene' "$f"; then
    { echo '<scene version="1">'; cat "$f"; echo '</scene>'; } > "$f.scene"
    mv "$f.scene" "$f"
  fi
  if out=$(xmllint --noout --schema "$xsd" "$f" 2>&1); then
    accepted=$((accepted + 1))
  else
    echo "$out"
    echo "REJECTED (should be valid): xml block number $doc_blocks of docs/scene-language.md"
    failures=$((failures + 1))
  fi
done
if [ "$doc_blocks" -lt 10 ]; then
  echo "fewer than 10 xml examples found in docs/scene-language.md"
  failures=$((failures + 1))
fi

# The bad scenes the schema must reject: the "xmllint | scenes/X.xml | TEXT" lines of the
# one bad-scene corpus, each rejected for the reason TEXT names (a substring of xmllint's
# message), so a file rejected for an unrelated reason (a typo in the test) fails too.
while IFS= read -r line; do
  case "$line" in "xmllint | "*) ;; *) continue ;; esac
  rest=${line#xmllint | }
  file="$src/tests/bad/${rest%% | *}"
  expect=${rest#* | }
  if [ ! -f "$file" ]; then
    echo "NO SUCH FILE: ${file#$src/}"
    failures=$((failures + 1))
    continue
  fi
  out=$(xmllint --noout --schema "$xsd" "$file" 2>&1)
  status=$?
  if [ $status -eq 0 ]; then
    echo "ACCEPTED (should be rejected): ${file#$src/}"
    failures=$((failures + 1))
  elif [ $status -ne 3 ] && [ $status -ne 4 ]; then
    echo "$out"
    echo "NOT A VALIDATION ERROR (xmllint status $status): ${file#$src/}"
    failures=$((failures + 1))
  elif ! grep -qF -- "$expect" <<<"$out"; then
    echo "$out"
    echo "REJECTED FOR ANOTHER REASON (expected \"$expect\"): ${file#$src/}"
    failures=$((failures + 1))
  else
    rejected=$((rejected + 1))
  fi
done <"$src/tests/bad/cases.txt"

# Guard against a vacuous pass (files moved, globs matching nothing).
if [ -z "$valid_files" ]; then
  echo "no valid scene found under examples/"
  failures=$((failures + 1))
fi
if [ "$rejected" -lt 8 ]; then
  echo "fewer than 8 bad files were checked"
  failures=$((failures + 1))
fi

if [ $failures -eq 0 ]; then
  echo "schema_validate: OK: $accepted valid scenes accepted ($doc_blocks from the reference), $rejected bad files rejected for the expected reason"
  exit 0
fi
echo "schema_validate: FAIL: $failures problem(s); $accepted valid scenes accepted, $rejected bad files rejected as expected"
exit 1
