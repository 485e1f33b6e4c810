#!/bin/bash
# The plotting scripts write as conescan's programs do, and run the interpreters the set-up
# installed into (ctest scripts.writers; docs/RELIABILITY.md, the third audit's items 9 and 16):
#  - no script finds its interpreter on PATH (a virtual environment's python3 without matplotlib, another
#    gnuplot): scripts/plot-fit.py and scripts/plot.sh run with a broken python3 and gnuplot
#    first in PATH;
#  - scripts/plot.sh never replaces its input or a read-only file, and under a file-size limit
#    says why, exits 1 and leaves nothing (it said "wrote");
#  - scripts/plot-fit.py with a file as OUTDIR says so in one line, exit 2 (a traceback).
# Skipped (77) without Debian's python3-matplotlib or gnuplot.
# Usage: plot_scripts.sh CONESCAN_SIM CONESCAN_FIT SOURCE_DIR
set -eu
sim=$1
fit=$2
source=$3
/usr/bin/python3 -c "import matplotlib, numpy" 2>/dev/null || exit 77
[ -x /usr/bin/gnuplot ] || exit 77
work=$(mktemp -d)
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
fail() {
  echo "scripts.writers: $*" >&2
  exit 1
}

# Interpreters: Debian's, by absolute path, in every script (the first line of a Python script;
# python3 and gnuplot commands in shell scripts).
for script in "$source"/scripts/*.py; do
  [ "$(head -n 1 "$script")" = "#!/usr/bin/python3" ] || fail "$script: first line is not #!/usr/bin/python3"
done
for script in "$source"/scripts/*.sh; do
  grep -nE '(^|[;|&$( ]|\$\()(python3|gnuplot) ' "$script" | grep -vE '^[0-9]+:[[:space:]]*#' |
    grep -v 'setup.sh' | sed "s|^|$script:|" || true
done >"$work/bare"
if [ -s "$work/bare" ]; then
  cat "$work/bare" >&2
  fail "a script runs python3 or gnuplot from PATH"
fi
mkdir "$work/bin"
for tool in python3 gnuplot; do
  printf '#!/bin/sh\necho "the %s first in PATH" >&2\nexit 3\n' "$tool" >"$work/bin/$tool"
  chmod +x "$work/bin/$tool"
done

# A small fit and a short CSV.
scene="--model scan --step-s 60 --orbits 1"
"$sim" $scene --seed 3 --head sigma=0.05,phase=60,noise=0.01 >"$work/telemetry.csv"
"$fit" --telemetry "$work/telemetry.csv" $scene --head noise=0.01 --free h1.sigma,h1.phase \
  --json >"$work/fit.json"
PATH="$work/bin:$PATH" "$source/scripts/plot-fit.py" "$work/fit.json" "$work/out" >/dev/null ||
  fail "plot-fit.py did not run with another python3 first in PATH"
test -s "$work/out/correlation.png" || fail "plot-fit.py wrote no correlation.png"

# plot-fit.py: a file as OUTDIR.
status=0
"$source/scripts/plot-fit.py" "$work/fit.json" "$work/telemetry.csv" 2>"$work/err" || status=$?
[ "$status" -eq 2 ] || fail "plot-fit.py with a file as OUTDIR: exit $status, not 2"
[ "$(wc -l <"$work/err")" -eq 1 ] && grep -q "is not a directory" "$work/err" ||
  { cat "$work/err" >&2; fail "plot-fit.py with a file as OUTDIR: not one line saying so"; }

# plot.sh: with another gnuplot first in PATH; never over its input; never over a read-only file;
# a file-size limit.
"$sim" --duration-s 300 >"$work/paper.csv"
cp "$work/paper.csv" "$work/paper.copy"
PATH="$work/bin:$PATH" "$source/scripts/plot.sh" "$work/paper.csv" "$work/paper.png" 2>/dev/null ||
  fail "plot.sh did not run with another gnuplot first in PATH"
status=0
"$source/scripts/plot.sh" "$work/paper.csv" "$work/paper.csv" 2>"$work/err" || status=$?
[ "$status" -eq 2 ] && cmp -s "$work/paper.csv" "$work/paper.copy" ||
  fail "plot.sh INPUT INPUT: exit $status, the input replaced or changed"
cp "$work/paper.png" "$work/kept.png"
chmod a-w "$work/kept.png"
status=0
"$source/scripts/plot.sh" "$work/paper.csv" "$work/kept.png" 2>"$work/err" || status=$?
[ "$status" -eq 1 ] && cmp -s "$work/kept.png" "$work/paper.png" ||
  fail "plot.sh over a read-only file: exit $status, or the file changed (as root too)"
status=0
(ulimit -f 4 && "$source/scripts/plot.sh" "$work/paper.csv" "$work/limited.png") 2>"$work/err" ||
  status=$?
[ "$status" -eq 1 ] || fail "plot.sh past a file-size limit: exit $status, not 1"
grep -q "cannot write" "$work/err" && ! grep -q "wrote" "$work/err" ||
  { cat "$work/err" >&2; fail "plot.sh past a file-size limit: no message, or 'wrote'"; }
[ -z "$(ls -A "$work" | grep -e limited -e '\.tmp-')" ] ||
  fail "plot.sh past a file-size limit left $(ls -A "$work" | grep -e limited -e '\.tmp-')"
echo "scripts.writers: ok"
