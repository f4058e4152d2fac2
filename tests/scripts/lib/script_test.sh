# The start every script test shares (tests/scripts/*.sh; CTest runs each as
# `bash NAME.sh <lucent-binary> <source-dir>`). Sourced right after `set -u`, it sets
#   lucent    the binary under test        src   the source folder
#   tmp       a fresh folder, removed at exit
#   fail MSG  prints "FAIL: MSG" on stderr and counts it in $failures
#   skip MSG  prints "SKIPPED: MSG" and ends the script with status 77, which CTest reports
#             as skipped (SKIP_RETURN_CODE in tests/CMakeLists.txt), never as passed
# This file is not a test itself: CTest takes only tests/scripts/*.sh.
lucent=${1:?usage: bash TEST.sh <lucent-binary> <source-dir>}
src=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
skip() { echo "SKIPPED: $*"; exit 77; }
