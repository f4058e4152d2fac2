#!/usr/bin/env bash
# bench/tile_schedule as a program: a trace gives a table and TSV rows, a malformed trace
# a message naming its line and a non-zero exit status, a synthetic map needs no trace.
# Usage: bash tile_schedule_cli.sh <path-to-tile_schedule>
set -u
sched=${1:?usage: bash tile_schedule_cli.sh <path-to-tile_schedule>}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# A 64x32 image in tiles of 16 (4 x 2), keys of the header in another order.
cat > "$tmp/good.txt" <<'TXT'
# lucent tile costs 1
# threads 1 tile 16 image 64 32 samples 4 load 0.25
x0 y0 x1 y1 seconds
0 0 16 16 0.01
16 0 32 16 0.02
32 0 48 16 0.01
48 0 64 16 0.01
0 16 16 32 0.04
16 16 32 32 0.01
32 16 48 32 0.01
48 16 64 32 0.01
TXT
"$sched" "$tmp/good.txt" --ranks 2,4 --tsv "$tmp/out.tsv" >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ "$status" -eq 0 ] || fail "good trace: exit status $status; stderr: $(cat "$tmp/stderr")"
grep -q '^| 4 |' "$tmp/stdout" || fail "good trace: no row for 4 ranks: $(cat "$tmp/stdout")"
grep -q '0.25 s load per rank' "$tmp/stdout" || fail "good trace: the header's load is not used"
grep -q 'optimistic' "$tmp/stdout" || fail "good trace: no words on where the model is optimistic"
# 2 rank counts x the tile sizes 16, 32, 64, 128, 256 (the larger ones one tile).
rows=$(grep -vc '^#' "$tmp/out.tsv")
[ "$rows" -eq 10 ] || fail "good trace: $rows TSV rows, expected 10"

# --cost-scale multiplies every tile's cost: the total is said 4 times larger (0.12 s to
# 0.48 s), and the same messages then weigh less against the rendering.
"$sched" "$tmp/good.txt" --ranks 4 --tiles 16 --tsv "$tmp/x1.tsv" >"$tmp/stdout1" 2>&1
"$sched" "$tmp/good.txt" --ranks 4 --tiles 16 --cost-scale 4 --tsv "$tmp/x4.tsv" >"$tmp/stdout4" 2>&1
grep -q '0.12 s in all' "$tmp/stdout1" || fail "cost scale 1: total: $(head -2 "$tmp/stdout1")"
grep -q 'costs x 4: .*0.48 s in all' "$tmp/stdout4" || fail "cost scale 4: total: $(head -2 "$tmp/stdout4")"
e1=$(grep -v '^#' "$tmp/x1.tsv" | head -1 | cut -f4)
e4=$(grep -v '^#' "$tmp/x4.tsv" | head -1 | cut -f4)
awk -v a="$e1" -v b="$e4" 'BEGIN { exit !(b > a) }' || fail "cost scale 4: efficiency $e4 not above $e1"
"$sched" "$tmp/good.txt" --cost-scale 0 >/dev/null 2>&1 && fail "--cost-scale 0: exit status 0"

sed 's/^16 16 32 32 0.01$/16 16 32 32 0.01 extra/' "$tmp/good.txt" > "$tmp/bad.txt"
"$sched" "$tmp/bad.txt" >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ "$status" -ne 0 ] || fail "malformed trace: exit status 0"
grep -q "bad.txt:9: expected 'x0 y0 x1 y1 seconds'" "$tmp/stderr" ||
  fail "malformed trace: message: $(cat "$tmp/stderr")"

"$sched" "$tmp/missing.txt" >/dev/null 2>"$tmp/stderr" && fail "missing trace: exit status 0"
grep -q "missing.txt: cannot open" "$tmp/stderr" || fail "missing trace: message: $(cat "$tmp/stderr")"
"$sched" "$tmp/good.txt" --tiles 24 >/dev/null 2>"$tmp/stderr" && fail "tile 24 of 16: exit status 0"
grep -q "not a multiple" "$tmp/stderr" || fail "tile 24 of 16: message: $(cat "$tmp/stderr")"

"$sched" --synthetic 256 128 --ranks 2,1024 --hot 0,0,0.5,0.5,10 >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ "$status" -eq 0 ] || fail "synthetic: exit status $status; stderr: $(cat "$tmp/stderr")"
grep -q '^| 1024 |' "$tmp/stdout" || fail "synthetic: no row for 1024 ranks"
"$sched" --synthetic 256 128 --hot 0,0,1 >/dev/null 2>"$tmp/stderr" && fail "bad --hot: exit status 0"
grep -q "five numbers" "$tmp/stderr" || fail "bad --hot: message: $(cat "$tmp/stderr")"

[ "$failures" -eq 0 ] && echo "tile_schedule_cli: all checks passed"
exit $((failures > 0))
