#!/usr/bin/env bash
# lucent compare --pov with a hand-written scene's assumed_gamma (povray/pov_gamma.h):
# gamma.xml against its twin with assumed_gamma 1.0 and against the same twin with 2.2.
# POV-Ray computes both with the same numbers, so both must match Lucent (PSNR >= 100 dB;
# read back with File_Gamma=1.0 the 2.2 one gives about 13 dB) and the 2.2 one is named in
# a warning and in POV-Ray's command line. An assumed_gamma that is an identifier is refused
# with exit status 3 and the reason, before anything is rendered.
# Usage: bash povray_compare_gamma.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

if ! command -v povray >/dev/null 2>&1 && [ -z "${LUCENT_POVRAY:-}" ]; then
  echo "FAIL: povray is not installed (scripts/install-deps installs it)" >&2
  exit 1
fi

json_number() { sed -n "s/^ *\"$2\": *\([^,]*\),*$/\1/p" "$1"; }
scenes="$src/tests/povray/scenes"

for g in 1 22; do
  out="$tmp/g$g"
  if ! "$lucent" compare "$scenes/gamma.xml" --pov "$scenes/gamma_$g.pov" -o "$out" \
       >"$tmp/stdout$g" 2>"$tmp/stderr$g"; then
    fail "assumed_gamma $g: lucent compare exited with $?: $(cat "$tmp/stderr$g")"
    continue
  fi
  psnr=$(json_number "$out/report.json" psnr_db)
  [ -n "$psnr" ] || { fail "assumed_gamma $g: no psnr_db in report.json"; continue; }
  if [ "$psnr" != "null" ] && ! awk -v p="$psnr" 'BEGIN { exit !(p >= 100) }'; then
    fail "assumed_gamma $g: PSNR $psnr dB < 100 dB"
  fi
  echo "assumed_gamma $g: PSNR $psnr dB"
done

grep -q "File_Gamma=1.0" "$tmp/g1/report.json" || fail "assumed_gamma 1.0: POV-Ray not run with File_Gamma=1.0"
grep -q "warning" "$tmp/stderr1" && fail "assumed_gamma 1.0: unexpected warning: $(cat "$tmp/stderr1")"
grep -q "File_Gamma=2.2" "$tmp/g22/report.json" || fail "assumed_gamma 2.2: POV-Ray not run with File_Gamma=2.2"
grep -qF "gamma_22.pov:4: assumed_gamma 2.2: POV-Ray computes with the scene's numbers as they are" \
  "$tmp/stderr22" || fail "assumed_gamma 2.2: no warning naming it: $(cat "$tmp/stderr22")"

# An assumed_gamma compare cannot read: refused, saying why.
sed 's/assumed_gamma 2.2/assumed_gamma Gamma/; s/^#version 3.7;/#version 3.7;\n#declare Gamma = 2.2;/' \
  "$scenes/gamma_22.pov" >"$tmp/named.pov"
"$lucent" compare "$scenes/gamma.xml" --pov "$tmp/named.pov" -o "$tmp/named" >/dev/null 2>"$tmp/stderr"
status=$?
[ "$status" -eq 3 ] || fail "assumed_gamma Gamma: exit status $status, expected 3"
grep -qF "named.pov: line 5: assumed_gamma Gamma is not a plain number or srgb: POV-Ray's output depends on its working gamma" \
  "$tmp/stderr" || fail "assumed_gamma Gamma: no reason given: $(cat "$tmp/stderr")"
[ ! -e "$tmp/named/povray-linear16.png" ] || fail "assumed_gamma Gamma: POV-Ray ran anyway"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "povray_compare_gamma: all checks passed"
