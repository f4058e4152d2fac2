#!/usr/bin/env bash
# Memory limits (docs/security.md): a mesh or an image too large for the memory left is
# refused with a clear error naming what it needs and what is available, not killed half
# way. Memory is capped with `ulimit -v`, so this runs only in builds without
# AddressSanitizer (which reserves terabytes of address space up front).
# Usage: bash memory_limits.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
if grep -q __asan_init "$lucent" 2>/dev/null; then
  skip "memory_limits: AddressSanitizer build (ulimit -v cannot be used)"
fi

# An open 1000x1000 grid: 10^6 vertices, about 2x10^6 triangles, 55 MB of OFF. Its repair
# pipeline needs about 1.27 GB; with 1 GB of address space (lucent itself takes about half)
# the file is read, then refused before the pipeline starts.
python3 - "$tmp" <<'PY'
import sys, os
n = 1000
with open(os.path.join(sys.argv[1], 'grid.off'), 'w') as f:
    f.write('OFF\n%d %d 0\n' % (n * n, 2 * (n - 1) * (n - 1)))
    f.write(''.join('%d %d 0\n' % (i, j) for j in range(n) for i in range(n)))
    for j in range(n - 1):
        f.write(''.join('3 %d %d %d\n3 %d %d %d\n' % (a, a + 1, a + n + 1, a, a + n + 1, a + n)
                        for a in range(j * n, j * n + n - 1)))
PY
printf '<scene version="1">\n<camera/>\n<mesh src="grid.off"/>\n</scene>\n' > "$tmp/scene.xml"
( ulimit -v 1000000; exec "$lucent" check "$tmp/scene.xml" ) >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ "$status" -eq 2 ] || fail "large mesh: exit status $status, expected 2; stderr: $(cat "$tmp/stderr")"
grep -qE "scene.xml:3:12: error: <mesh> attribute 'src': cannot read the mesh 'grid.off': the mesh \(1000000 vertices, 1996002 faces\) needs about 1\.[0-9] GB of memory, more than the [0-9.]+ (MB|GB) available" "$tmp/stderr" ||
  fail "large mesh: message: $(cat "$tmp/stderr")"

# A 20000x20000 image needs 14.4 GB: refused before the render starts, the old image kept.
printf '<scene version="1">\n<camera/>\n<sphere radius="1"/>\n</scene>\n' > "$tmp/small.xml"
echo "old image" > "$tmp/out.png"
( ulimit -v 1000000; exec "$lucent" render "$tmp/small.xml" -o "$tmp/out.png" -w 20000 -h 20000 -q ) >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ "$status" -eq 3 ] || fail "large image: exit status $status, expected 3; stderr: $(cat "$tmp/stderr")"
grep -qE "^lucent: error: a 20000x20000 image needs about 14\.4 GB of memory, more than the [0-9.]+ (MB|GB) available" "$tmp/stderr" ||
  fail "large image: message: $(cat "$tmp/stderr")"
[ "$(cat "$tmp/out.png")" = "old image" ] || fail "large image: the old image was changed"

[ "$failures" -eq 0 ] && echo "memory_limits: all checks passed"
exit $((failures > 0))
