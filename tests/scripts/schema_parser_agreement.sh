#!/usr/bin/env bash
# docs/lucent.xsd and Lucent's parser must agree on the lexical edge cases listed in
# tests/lang/schema/lexical_cases.txt: each line says whether both accept the value, both
# reject it, or only the parser rejects it (a rule XML Schema 1.0 cannot express). Above
# all, the schema must never reject a value the parser accepts, or editors would flag
# valid scenes.
# Run by CTest as: bash schema_parser_agreement.sh <lucent-binary> <source-dir>
set -u

lucent=${1:?usage: schema_parser_agreement.sh <lucent-binary> <source-dir>}
src=${2:?usage: schema_parser_agreement.sh <lucent-binary> <source-dir>}
xsd="$src/docs/lucent.xsd"
cases="$src/tests/lang/schema/lexical_cases.txt"

if ! command -v xmllint >/dev/null; then
  echo "schema_parser_agreement: FAIL: xmllint not found (Debian package libxml2-utils)"
  exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene="$work/case.xml"

failures=0
count=0
while IFS= read -r line; do
  case "$line" in '#'* | '') continue ;; esac
  IFS='|' read -r expect element attribute value <<<"$line"
  # The value may hold characters that are special in XML.
  value_xml=$(printf '%s' "$value" | sed -e 's/&/\&amp;/g' -e 's/"/\&quot;/g' -e 's/</\&lt;/g')
  attr="$attribute=\"$value_xml\""
  case "$element" in
    render) body="<render $attr/><camera/>" ;;
    camera) body="<camera $attr/>" ;;
    light) body="<camera/><light position=\"0 5 0\" $attr/>" ;;
    mesh) body="<camera/><mesh positions=\"0 0 0 1 0 0 0 1 0\" indices=\"0 1 2\" $attr/>" ;;
    param) body="<param name=\"r\" value=\"1\"/><camera/><sphere $attr/>" ;;
    *) body="<camera/><$element $attr/>" ;;
  esac
  printf '<scene version="1">%s</scene>\n' "$body" >"$scene"
  count=$((count + 1))

  "$lucent" check "$scene" >/dev/null 2>"$work/parser.err"
  parser_status=$?
  xmllint --noout --schema "$xsd" "$scene" >/dev/null 2>"$work/schema.err"
  schema_status=$?
  # Anything but "accepted" or "rejected" (a crash, a schema that does not compile) fails.
  if [ $parser_status -ne 0 ] && [ $parser_status -ne 2 ]; then
    echo "PARSER FAILED (status $parser_status) on <$element $attribute=\"$value\">"
    cat "$work/parser.err"
    failures=$((failures + 1))
    continue
  fi
  if [ $schema_status -ne 0 ] && [ $schema_status -ne 3 ] && [ $schema_status -ne 4 ]; then
    echo "XMLLINT FAILED (status $schema_status) on <$element $attribute=\"$value\">"
    cat "$work/schema.err"
    failures=$((failures + 1))
    continue
  fi
  parser=$([ $parser_status -eq 0 ] && echo accepts || echo rejects)
  schema=$([ $schema_status -eq 0 ] && echo accepts || echo rejects)
  case "$expect" in
    valid) want_parser=accepts want_schema=accepts ;;
    invalid) want_parser=rejects want_schema=rejects ;;
    parser-only) want_parser=rejects want_schema=accepts ;;
    *)
      echo "BAD LINE in lexical_cases.txt: $line"
      failures=$((failures + 1))
      continue
      ;;
  esac
  if [ "$parser" != "$want_parser" ] || [ "$schema" != "$want_schema" ]; then
    echo "MISMATCH <$element $attribute=\"$value\">: expected $expect, but the parser $parser and the schema $schema"
    [ "$parser" = accepts ] || head -n 2 "$work/parser.err"
    [ "$schema" = accepts ] || head -n 2 "$work/schema.err"
    failures=$((failures + 1))
  fi
done <"$cases"

if [ $count -lt 50 ]; then
  echo "fewer than 50 cases read from $cases"
  failures=$((failures + 1))
fi
if [ $failures -eq 0 ]; then
  echo "schema_parser_agreement: OK: $count cases judged as expected by the parser and the schema"
  exit 0
fi
echo "schema_parser_agreement: FAIL: $failures of $count cases"
exit 1
