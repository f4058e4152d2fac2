# Shared by bench/pov_samples.sh and bench/pov_samples_speed.sh: the .ini file of a sample
# scene, its frames, and a command timed in CPU seconds. Sourced; the timed commands'
# messages go to $work/err.
# The .ini file of a scene: one in its folder whose Input_File_Name names it, else one of
# the same name.
iniOf() {
  local pov=$1 dir name ini
  dir=$(dirname "$pov")
  name=$(basename "$pov")
  for ini in "$dir"/*.ini; do
    [ -f "$ini" ] || continue
    if grep -qiE "^[[:space:]]*Input_File_Name[[:space:]]*=[[:space:]]*\"?$name\"?[[:space:]]*(;.*)?$" "$ini"; then
      echo "$ini"
      return
    fi
  done
  [ -f "${pov%.pov}.ini" ] && echo "${pov%.pov}.ini"
}

# An .ini file's Initial_Frame (1 when it has none).
iniFirst() {
  local first
  first=$(grep -iE '^[[:space:]]*Initial_Frame[[:space:]]*=' "$1" 2>/dev/null | tail -1 | sed 's/.*=[[:space:]]*//; s/[[:space:];].*//')
  echo "${first:-1}"
}

# The middle frame (1-based, as --frame counts) of an .ini file's animation; 1 without one.
middleFrame() {
  local ini=$1 first last
  first=$(grep -iE '^[[:space:]]*Initial_Frame[[:space:]]*=' "$ini" | tail -1 | sed 's/.*=[[:space:]]*//; s/[[:space:];].*//')
  last=$(grep -iE '^[[:space:]]*Final_Frame[[:space:]]*=' "$ini" | tail -1 | sed 's/.*=[[:space:]]*//; s/[[:space:];].*//')
  first=${first:-1}
  last=${last:-$first}
  echo $(((last - first) / 2 + 1))
}

# CPU seconds (user + system) of a command, into the variable cpu; its status returned.
TIMEFORMAT='%3U %3S'
timed() {
  local t status
  { t=$( { time "$@" >/dev/null 2>>"$work/err"; } 2>&1 ); } 
  status=$?
  cpu=$(echo "$t" | tail -1 | awk '{printf "%.3f", $1 + $2}')
  return $status
}

# The arguments that render sample scene $pov as the measurements do: 320x240, with its .ini
# (an animation at its middle frame). Sets ini, frame, args (lucent check and render),
# frameArgs (lucent render, compare), checkFrame (lucent check) and povArgs (povray, one
# thread, no antialiasing, no display, writing $work/pov.png).
sceneArgs() {
  local pov=$1
  name=$(basename "$pov")
  ini=$(iniOf "$pov")
  frame=1
  args=(-w 320 -h 240)
  frameArgs=()
  checkFrame=()
  povArgs=(+I"$name" +W320 +H240 -D -V -GS -GR -A +WT1 +FN +O"$work/pov.png")
  if [ -n "$ini" ]; then
    args+=(--pov-ini "$ini")
    povArgs=("$ini" "${povArgs[@]}")
    frame=$(middleFrame "$ini")
    if [ "$frame" -gt 1 ]; then
      frameArgs=(--frame "$frame")
      checkFrame=(-D "frame=$frame")
      povArgs+=(+SF"$(($(iniFirst "$ini") + frame - 1))" +EF"$(($(iniFirst "$ini") + frame - 1))")
    fi
  fi
}

# The CPU seconds of the whole process, one thread, one sample, 320x240, of `lucent render`
# and of `povray` on the scene named by sceneArgs, in the current folder (a copy of the
# scene's, where it may write). Sets lucentCpu and povCpu (empty where the run failed) and
# ratio (POV-Ray over Lucent).
timeRenders() {
  lucentCpu="" povCpu="" ratio=""
  timed timeout 600 "$lucent" render "${args[@]}" "${frameArgs[@]/--frame/--frames}" \
    --allow-write "$PWD" -s 1 -t 1 -q -o "$work/lucent.png" "$name" && lucentCpu=$cpu
  timed timeout 1200 povray "${povArgs[@]}" && povCpu=$cpu
  if [ -n "$lucentCpu" ] && [ -n "$povCpu" ]; then
    ratio=$(awk -v p="$povCpu" -v l="$lucentCpu" 'BEGIN { if (l > 0) printf "%.2f", p / l }')
  fi
  return 0
}
