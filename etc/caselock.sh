# caselock.sh - one run at a time in a tutorial's folder (sourced by the tutorials'
# Allrun and Allclean; bash).
#
# A run of hours must not be cleaned, resumed or run again beside itself: a second
# Allrun in the same folder would clean it and write into it while the first is
# still writing. The lock is flock(1) on the case's Allrun script (a file the
# repository holds, so no clean removes it and every copy of a case has its own);
# the kernel drops it when every process that holds the
# descriptor has ended (the run's shell and the programs it started), so a lock
# left by a run that was killed is free again by itself. Both calls wait up to
# 10 s for it (the processes of a run just stopped take a moment to end;
# SNOWWALL_LOCK_WAIT seconds instead, a whole number from 0).
#
#   case_lock WHO             take the folder's lock for the rest of this shell
#       (descriptor 9), or refuse: exit 2 with one message naming the run that
#       holds it (Allrun.owner: its pid, host, start and options). Says when it
#       takes the folder over from a run that is no longer running, and exports
#       SNOWWALL_CASE_LOCK (the folder) so that the run's own Allclean does not
#       ask again.
#   case_lock_claim [ARGS...]  write Allrun.owner for this run (after the run's
#       last refusal: a refused run leaves nothing behind).
#   case_lock_ended           the run ended (an EXIT trap): said in Allrun.owner.
#
# The tutorials' Allclean checks the same lock by itself (a copy of a case cleans
# without the repository): refused while another run holds it, Allrun.owner
# removed with the rest otherwise; inside the run that holds it
# (SNOWWALL_CASE_LOCK is this folder) it passes and keeps Allrun.owner.
#
# Both work in the current folder (the case's), which must hold Allrun.

case_lock_wait() {   # the seconds to wait for the lock
    case "${SNOWWALL_LOCK_WAIT:-10}" in
        ''|*[!0-9]*) echo "caselock: SNOWWALL_LOCK_WAIT '${SNOWWALL_LOCK_WAIT}' is not a whole number of seconds" >&2; exit 2 ;;
    esac
    echo "${SNOWWALL_LOCK_WAIT:-10}"
}

case_lock_owner() {   # the holder as one line, from Allrun.owner
    if [ -s Allrun.owner ]; then
        awk '$1 == "pid" { p = $2 } $1 == "host" { h = $2 } $1 == "started" { $1 = ""; s = substr($0, 2) }
             $1 == "options" { $1 = ""; o = substr($0, 2) }
             END { printf "pid %s on %s, started %s, options: %s", p, h, s, (o == "" ? "(none)" : o) }' Allrun.owner
    else
        printf 'a process that wrote no Allrun.owner'
    fi
}

case_lock() {
    local who=$1
    command -v flock > /dev/null || { echo "$who: 'flock' not found (util-linux): the folder cannot be locked" >&2; exit 2; }
    [ -f Allrun ] || { echo "$who: no Allrun in $(pwd): not a case folder" >&2; exit 2; }
    # Allrun.owner is written here: never through a link, into a FIFO or over a device
    if [ -L Allrun.owner ] || { [ -e Allrun.owner ] && [ ! -f Allrun.owner ]; }; then
        echo "$who: $(pwd)/Allrun.owner is not a file a run wrote (a link, folder, FIFO or device): move it away" >&2
        exit 2
    fi
    exec 9< Allrun
    local wait
    wait=$(case_lock_wait) || exit 2
    if ! flock -w "$wait" 9; then
        echo "$who: another run is writing this folder ($(pwd)): $(case_lock_owner);" \
             "wait for it to end, or stop it (kill -- -PID for its whole process group), then start again" >&2
        exit 2
    fi
    if [ -s Allrun.owner ] && ! grep -q '^ended' Allrun.owner; then
        echo "$who: the last run here ($(case_lock_owner)) is no longer running and did not end; its folder is taken over" >&2
    fi
    export SNOWWALL_CASE_LOCK="$PWD"
}

case_lock_claim() {
    {
        printf 'pid %s\nhost %s\nstarted %s\n' "$$" "$(hostname)" "$(date '+%Y-%m-%d %H:%M:%S %z')"
        printf 'options %s\n' "$*"
    } > Allrun.owner
    case_lock_claimed=1
}

case_lock_ended() {   # only a run that claimed the folder marks its end
    [ "${case_lock_claimed:-0}" = 1 ] && [ -f Allrun.owner ] || return 0
    printf 'ended %s\n' "$(date '+%Y-%m-%d %H:%M:%S %z')" >> Allrun.owner
}
