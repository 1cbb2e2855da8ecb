#!/usr/bin/env bash
# An installed curvsph runs an installed case from any directory (issue 35 item 3): the
# shipped cases are copied out of PREFIX/share/curvsph/cases to a folder of their own and run
# from a third directory, so the data files they name (../data/... beside the case: absent
# there) must come from PREFIX/share/curvsph/data. A case naming a missing file must stop
# with exit 2 and list every place looked in. Usage: installed_case.sh PREFIX
set -u
prefix=$(cd "$1" && pwd)
bin="$prefix/bin/curvsph"
share="$prefix/share/curvsph"
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -x "$bin" ] || fail "no installed binary $bin"
for f in cases/dam_break_2d.yaml cases/u_pipe_at_rest.yaml data/cad/u_pipe.step scripts/vtp.py; do
  [ -f "$share/$f" ] || fail "not installed: $share/$f"
done
[ -f "$prefix/share/doc/curvsph/docs/manual.md" ] || fail "docs/manual.md not installed"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/mine" "$work/elsewhere"
cp "$share/cases/dam_break_2d.yaml" "$share/cases/u_pipe_at_rest.yaml" "$work/mine/"
cd "$work/elsewhere" || fail "cd"

# The 2-D dam break reads the Martin & Moyce record (analysis.surge_front.experiment).
"$bin" run ../mine/dam_break_2d.yaml --out dam --threads 1 --quiet \
  --set resolution.dx=0.01 --set time.end=0.01 > dam.txt 2>&1 || { cat dam.txt; fail "dam_break_2d: exit $?"; }
[ -f dam/metrics.json ] || fail "dam_break_2d wrote no metrics.json"
# The U-bend pipe reads its STEP part (walls.0.file), coarse: a few hundred particles.
"$bin" run ../mine/u_pipe_at_rest.yaml --out pipe --threads 1 --quiet \
  --set time.end=0.0005 > pipe.txt 2>&1 || { cat pipe.txt; fail "u_pipe_at_rest: exit $?"; }
[ -f pipe/metrics.json ] || fail "u_pipe_at_rest wrote no metrics.json"

# A file found nowhere: exit 2, the key named, beside the case and the data folder listed.
"$bin" run ../mine/u_pipe_at_rest.yaml --out missing --threads 1 --quiet \
  --set walls.0.file=no_such_part.step > missing.txt 2>&1
rc=$?
[ "$rc" -eq 2 ] || { cat missing.txt; fail "missing file: exit $rc, expected 2"; }
grep -q "walls.0.file" missing.txt || { cat missing.txt; fail "message does not name the key"; }
grep -q "$work/elsewhere/../mine/no_such_part.step\|../mine/no_such_part.step" missing.txt ||
  { cat missing.txt; fail "message does not list the case's folder"; }
grep -q "share/curvsph/data/no_such_part.step" missing.txt ||
  { cat missing.txt; fail "message does not list the data folder"; }
echo "installed cases run from $work/elsewhere"
