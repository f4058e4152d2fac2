#!/usr/bin/env bash
# The bad-input corpus (tests/bad/cases.txt): every case must end with its expected exit
# status and message within a time limit, and never crash (a signal, or a sanitizer report
# in the LUCENT_SANITIZE build, which also checks for leaks at exit).
# Usage: bash bad_inputs.sh <path-to-lucent> <source-dir> [CPU seconds per case, default 10]
# "Within a few seconds" is measured in CPU time (ulimit -t: SIGXCPU past it), which a
# loaded machine does not stretch; `timeout` adds a wall-clock limit six times longer for a
# case that hangs without using the CPU. Either counts as a failure.
set -u
lucent=$1
bad="$2/tests/bad"
limit=${3:-10}
wall=$((limit * 6))
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
cases=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# Generated inputs, too large or too odd to keep in the repository.
mkdir -p "$tmp/gen/chain" "$tmp/gen/links"
# 100,000 nested elements: an error, not a stack overflow.
python3 - "$tmp/gen" <<'PY'
import sys, os
d = sys.argv[1]
n = 100000
with open(os.path.join(d, 'deep.xml'), 'w') as f:
    f.write('<scene version="1">\n<camera/>\n' + '<group>' * n + '</group>' * n + '\n</scene>\n')
# A <use> chain deeper than the instance limit (1024).
with open(os.path.join(d, 'use_chain.xml'), 'w') as f:
    f.write('<scene version="1">\n<camera/>\n<defs>\n<sphere id="n0" radius="1"/>\n')
    for i in range(1, 1100):
        f.write('<group id="n%d"><use ref="n%d"/></group>\n' % (i, i - 1))
    f.write('</defs>\n<use ref="n1099"/>\n</scene>\n')
# A transform of 20,000 operations (long, valid) on a sphere of radius -1 (invalid).
with open(os.path.join(d, 'long_transform.xml'), 'w') as f:
    f.write('<scene version="1">\n<camera/>\n<sphere radius="-1" transform="' +
            'rotate-y(1) ' * 20000 + '"/>\n</scene>\n')
# Includes 20 deep (the limit is 16).
for i in range(20):
    with open(os.path.join(d, 'chain', 'c%d.xml' % i), 'w') as f:
        f.write('<scene version="1">\n' + ('<camera/>\n' if i == 0 else '') +
                ('<include src="c%d.xml"/>\n' % (i + 1) if i < 19 else '') + '</scene>\n')
# 200,000 spheres, each with an error: the error list must not take long.
with open(os.path.join(d, 'many_errors.xml'), 'w') as f:
    f.write('<scene version="1">\n<camera/>\n' + '<sphere radius="-1"/>\n' * 200000 + '</scene>\n')
PY
# Symbolic links that leave the scene's folder.
ln -s /etc/hostname "$tmp/gen/links/outside.xml"
ln -s /dev/zero "$tmp/gen/links/zero.obj"
ln -s /etc "$tmp/gen/links/etc"
printf '<scene version="1">\n<camera/>\n<include src="outside.xml"/>\n</scene>\n' > "$tmp/gen/links/include_link.xml"
printf '<scene version="1">\n<camera/>\n<mesh src="zero.obj"/>\n</scene>\n' > "$tmp/gen/links/mesh_link.xml"
printf '<scene version="1">\n<camera/>\n<include src="etc/hostname"/>\n</scene>\n' > "$tmp/gen/links/folder_link.xml"
# A file where a folder should be, and an image to protect.
echo "a file" > "$tmp/file"
cp "$bad/scenes/valid.xml" "$tmp/gen/valid.xml"

before=$(cd "$bad" && find . -print0 | sort -z | xargs -0 md5sum 2>/dev/null)

# cases.txt: STATUS | ARGUMENTS | EXPECTED STDERR SUBSTRING [| MORE...]  ('#' starts a
# comment). ARGUMENTS are split at spaces; $TMP is the scratch folder above. Run in tests/bad.
cd "$bad" || exit 1
while IFS= read -r line; do
  [[ "$line" =~ ^[[:space:]]*(#|$) ]] && continue
  [[ "$line" == "xmllint | "* ]] && continue  # the schema's expectation (schema_validate.sh)
  want=$(echo "${line%%|*}" | tr -d ' ')
  rest=${line#*|}
  argtext=${rest%%|*}
  expected=${rest#*|}
  expected=${expected# }
  # Each " | "-separated field of EXPECTED must appear.
  mapfile -t wants < <(printf '%s' "$expected" | awk 'BEGIN { RS = " \\| " } { sub(/\n$/, ""); print }')
  argtext=${argtext//\$TMP/$tmp}
  read -r -a args <<<"$argtext"
  cases=$((cases + 1))
  ( ulimit -t "$limit"; exec timeout -s KILL "$wall" "$lucent" "${args[@]}" ) </dev/null >"$tmp/stdout" 2>"$tmp/stderr"
  got=$?
  what="lucent $argtext"
  if [ "$got" -eq 137 ] || [ "$got" -eq 152 ]; then
    fail "$what: did not finish within ${limit} CPU seconds or ${wall} s"
  elif [ "$got" -ge 128 ]; then
    fail "$what: crashed (exit status $got): $(tail -c 2000 "$tmp/stderr")"
  elif grep -qE 'Sanitizer|runtime error:|internal error' "$tmp/stderr"; then
    fail "$what: sanitizer or internal error: $(head -c 3000 "$tmp/stderr")"
  elif [ "$got" -ne "$want" ]; then
    fail "$what: exit status $got, expected $want; stderr: $(head -c 1000 "$tmp/stderr")"
  else
    for want_text in "${wants[@]}"; do
      if ! grep -qF -- "$want_text" "$tmp/stderr"; then
        fail "$what: stderr lacks '$want_text': $(head -c 1000 "$tmp/stderr")"
        break
      fi
    done
  fi
done < cases.txt

leftovers=$(find "$bad" "$tmp" -name '.*lucent-*' -o -name '*.partial.*' | wc -l)
[ "$leftovers" -eq 0 ] || fail "files left behind: $(find "$bad" "$tmp" -name '.*lucent-*' -o -name '*.partial.*')"
# Nothing was written into the corpus (a scene's folder): same files, same contents.
after=$(cd "$bad" && find . -print0 | sort -z | xargs -0 md5sum 2>/dev/null)
[ "$before" = "$after" ] || fail "the corpus folder changed: $(diff <(echo "$before") <(echo "$after"))"
[ "$cases" -ge 100 ] || fail "only $cases cases in cases.txt"
[ "$failures" -eq 0 ] && echo "bad_inputs: all $cases cases behaved"
exit $((failures > 0))
