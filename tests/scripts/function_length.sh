#!/usr/bin/env bash
# No function of the renderer, the application layer, the command or lucent-mpi is longer
# than 80 lines (scripts/check-function-length): the ray path and the render loop stay in
# parts a reader can follow. The checker itself is held to hand-made
# files: it fails on a function of 81 lines, wherever the braces, strings and comments are,
# and passes one of 80.
# Run by CTest as: bash function_length.sh <lucent-binary> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
check="$src/scripts/check-function-length"

(cd "$src" && python3 "$check" render app cli mpi) >"$tmp/out" 2>&1 ||
  { cat "$tmp/out"; fail "a function of the render loop is longer than 80 lines"; }

# body N: N - 2 lines of statements (a function of N lines with a one-line signature), with
# what could mislead a brace counter.
body() {
  local i
  for ((i = 0; i < $1 - 2; ++i)); do
    case $((i % 4)) in
      0) echo '  s += "{ not a brace";  // } nor this' ;;
      1) echo "  c = '}';" ;;
      2) echo '  auto f = [&](int x) { return x + 1; };' ;;
      3) echo '  /* { */ n = f(n);' ;;
    esac
  done
}
# A template with its signature on two lines, a constructor whose initialiser list has
# braces, and a member defined in its class: 81 lines each from the template line or name.
{
  echo '#include <string>'
  echo 'namespace ns {'
  echo 'template <class T>'
  echo 'int longTemplate(T n,'
  echo '                 std::string s) {'
  body 79
  echo '}'
  echo 'struct Widget {'
  echo '  Widget(int a) : a_(a), b_{a} {'
  body 81
  echo '  }'
  echo '  int a_, b_;'
  echo '  int member() const {'
  body 81
  echo '  }'
  echo '};'
  echo 'const int kTable[] = {1, 2, 3};'
  echo '}  // namespace ns'
} >"$tmp/long.cpp"
python3 "$check" "$tmp/long.cpp" >"$tmp/out" 2>&1 && fail "functions of 81 lines passed"
for want in "long.cpp:3: longTemplate is 81 lines (at most 80)" "long.cpp:85: Widget is 81 lines (at most 80)" \
            "long.cpp:167: member is 81 lines (at most 80)"; do
  grep -qF "$want" "$tmp/out" || fail "the check did not say '$want': $(cat "$tmp/out")"
done
[ "$(wc -l <"$tmp/out")" -eq 3 ] || fail "the check found more than the three: $(cat "$tmp/out")"
# The same at 80 lines pass.
{
  echo 'int shortEnough(int n) {'
  body 80
  echo '}'
} >"$tmp/short.cpp"
python3 "$check" "$tmp/short.cpp" >"$tmp/out" 2>&1 || fail "a function of 80 lines failed: $(cat "$tmp/out")"
python3 "$check" --limit 79 "$tmp/short.cpp" >"$tmp/out" 2>&1 && fail "--limit 79 passed a function of 80 lines"
# An allowance for a function that is short is refused.
python3 "$check" --allow "$tmp/short.cpp:shortEnough" "$tmp/short.cpp" >"$tmp/out" 2>&1 &&
  fail "an allowance that no longer applies passed"
grep -qF "short.cpp:shortEnough: allowed to be longer than 80 lines, but it is not" "$tmp/out" ||
  fail "stale allowance message: $(cat "$tmp/out")"

[ "$failures" -eq 0 ] && echo "function length: all checks passed"
exit $((failures > 0))
