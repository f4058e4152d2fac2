#!/usr/bin/env bash
# The node limit of <repeat> (docs/scene-language.md): a repeat of 10^6 inside a repeat of
# 10^6 is refused before anything is expanded, with an error at the outermost repeat. That
# "before" is checked by memory, not time: the peak resident set size of `lucent check` on
# the refused scene (GNU time's "Maximum resident set size") stays within a few MB of the
# same command on a one-sphere scene. Expanding even 1% of the 10^12 spheres would take
# gigabytes (a Node is over 200 bytes).
# Usage: bash repeat_node_limit.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
[ -x /usr/bin/time ] || { echo "FAIL: /usr/bin/time (Debian package time) is missing"; exit 1; }

# Runs `lucent check FILE`: its peak RSS in kB in $rss, exit status in $status, stderr in
# $tmp/stderr.
peak() {
  /usr/bin/time -v -o "$tmp/time" "$lucent" check "$1" >"$tmp/stdout" 2>"$tmp/stderr"
  status=$?
  rss=$(sed -n 's/^[[:space:]]*Maximum resident set size (kbytes): //p' "$tmp/time")
}

printf '<scene version="1">\n  <camera/>\n  <sphere radius="1"/>\n</scene>\n' > "$tmp/one.xml"
peak "$tmp/one.xml"
base=$rss
[ "$status" -eq 0 ] || fail "one sphere: exit status $status; stderr: $(cat "$tmp/stderr")"

# Allowance over the baseline: 16 MB, far below what any real expansion would take.
allow=16384
check_refused() {  # FILE EXPECTED-MESSAGE
  peak "$1"
  [ "$status" -eq 2 ] || fail "$1: exit status $status, expected 2; stderr: $(cat "$tmp/stderr")"
  grep -qF -- "$2" "$tmp/stderr" || fail "$1: expected '$2' in stderr: $(cat "$tmp/stderr")"
  [ -n "$rss" ] && [ "$rss" -le $((base + allow)) ] ||
    fail "$1: peak RSS ${rss:-?} kB, more than the one-sphere scene's $base kB + $allow kB: it expanded"
  echo "$1: peak RSS $rss kB (one sphere: $base kB)"
}

check_refused "$src/tests/bad/scenes/repeat_node_limit.xml" \
  "repeat_node_limit.xml:3:3: error: this <repeat> would expand the scene to about 2e+12 nodes, lights and repeat instances, more than the limit of 10000000"

# The same in a group, and through a parameter for the count: still refused up front.
cat > "$tmp/grouped.xml" <<'EOF'
<scene version="1">
  <camera/>
  <param name="n" value="1000000"/>
  <group>
    <repeat var="i" count="$n">
      <group>
        <repeat var="j" count="${n / 2}">
          <sphere center="${i} ${j} 0" radius="0.1"/>
        </repeat>
      </group>
    </repeat>
  </group>
</scene>
EOF
check_refused "$tmp/grouped.xml" "grouped.xml:5:5: error: this <repeat> would expand the scene to about"

# Three levels of 1000: 10^9, refused at the outermost.
cat > "$tmp/three.xml" <<'EOF'
<scene version="1">
  <camera/>
  <repeat var="i" count="1000">
    <repeat var="j" count="1000">
      <repeat var="k" count="1000">
        <sphere radius="0.1"/>
      </repeat>
    </repeat>
  </repeat>
</scene>
EOF
check_refused "$tmp/three.xml" "three.xml:3:3: error: this <repeat> would expand the scene to about"

# The measure is not blind: a scene that really expands 200,000 spheres (valid, under the
# limit) does go over the allowance.
cat > "$tmp/expands.xml" <<'EOF'
<scene version="1">
  <camera/>
  <repeat var="i" count="500">
    <repeat var="j" count="400">
      <sphere center="${i} ${j} 0" radius="0.1"/>
    </repeat>
  </repeat>
</scene>
EOF
peak "$tmp/expands.xml"
[ "$status" -eq 0 ] || fail "200,000 spheres: exit status $status; stderr: $(cat "$tmp/stderr")"
[ -n "$rss" ] && [ "$rss" -gt $((base + allow)) ] ||
  fail "200,000 spheres: peak RSS ${rss:-?} kB is within the allowance: the measure cannot tell expansion"
echo "200,000 spheres expanded: peak RSS $rss kB"

[ "$failures" -eq 0 ] && echo "repeat_node_limit: all checks passed"
exit $((failures > 0))
