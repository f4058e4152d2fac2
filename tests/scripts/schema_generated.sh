#!/usr/bin/env bash
# docs/lucent.xsd is generated: it must equal what `lucent schema` prints from the shape
# registry and lang/schema_template.xsd (regenerate with `lucent schema -o docs/lucent.xsd`).
# Run by CTest as: bash schema_generated.sh <lucent-binary> <source-dir>
set -u
lucent=${1:?usage: schema_generated.sh <lucent-binary> <source-dir>}
src=${2:?usage: schema_generated.sh <lucent-binary> <source-dir>}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! "$lucent" schema >"$work/stdout.xsd"; then
  echo "schema_generated: FAIL: lucent schema failed"
  exit 1
fi
"$lucent" schema -o "$work/file.xsd" || { echo "schema_generated: FAIL: lucent schema -o failed"; exit 1; }
if ! cmp -s "$work/stdout.xsd" "$work/file.xsd"; then
  echo "schema_generated: FAIL: 'lucent schema' and 'lucent schema -o' differ"
  exit 1
fi
if ! diff -u "$src/docs/lucent.xsd" "$work/stdout.xsd" >"$work/diff"; then
  head -40 "$work/diff"
  echo "schema_generated: FAIL: docs/lucent.xsd differs from 'lucent schema'; regenerate it"
  exit 1
fi
echo "schema_generated: docs/lucent.xsd equals 'lucent schema' ($(wc -l <"$src/docs/lucent.xsd") lines)"
