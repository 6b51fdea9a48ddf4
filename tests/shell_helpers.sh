# What the shell tests share (sourced): a count of checks passed and failed, and a run ended by
# SIGTERM once it has written what a glob names.
fails=0 passes=0
pass() { passes=$((passes + 1)); }
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# terminate_once GLOB -- COMMAND...: COMMAND started in the background and sent SIGTERM as soon
# as a file matches GLOB (polled every 5 ms for up to 10 s); sets `seen` (1 where one did) and
# `term_rc`, COMMAND's exit status.
terminate_once() {
  local glob=$1
  shift 2
  "$@" &
  local pid=$!
  seen=0
  for _ in $(seq 2000); do
    if compgen -G "$glob" >/dev/null; then seen=1; break; fi
    sleep 0.005
  done
  kill -TERM "$pid"
  wait "$pid"
  term_rc=$?
}
