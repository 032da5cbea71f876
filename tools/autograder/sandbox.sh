#!/bin/sh
# sandbox.sh: where the autograder runs a student's code: as an unprivileged
# user of its own, under limits, and with everything it started ended after.
#
#   sh sandbox.sh run SLOT -- PROGRAM [ARG...]   PROGRAM as SLOT's user (below)
#   sh sandbox.sh prepare SLOT DIR               DIR given to SLOT's user
#   sh sandbox.sh cleanup SLOT                   every process of SLOT's user killed
#   sh sandbox.sh uid SLOT                       SLOT's user id
#   sh sandbox.sh cleanup-all                    every slot's
#
# Run as root (the autograder's run_autograder and tools/grade.sh, which
# GRADE_SANDBOX names this for). SLOT is a number: the user is the SLOT-th of
# AUTOGRADER_USERS ("grader-student0 grader-student1" by default; setup.sh
# creates them), so that tests run side by side each have a user, and ending
# one's processes leaves the other's alone.
#
# PROGRAM runs with only the environment it needs (PATH, HOME, LC_ALL, and
# what tools/grade.sh passes a test: TEST_OUTPUT, TEST_FILTER, BIN_DIR,
# TOOL_DIR, GRADE_OBSERVE_FD), its descriptors as given, and these limits
# (AUTOGRADER_LIMIT_* overrides each): address space 4 GiB, 256 processes of
# the user, files of 256 MiB, no core dumps. CPU time and output are
# tools/time_limit's, around this.
set -eu
prog=sandbox
users=${AUTOGRADER_USERS:-grader-student0 grader-student1}

user_of() { # user_of SLOT
    case $1 in ''|*[!0-9]*) echo "$prog: error: slot $1: want a number" >&2; exit 2 ;; esac
    set -- "$1" $users
    shift "$(($1 + 1))" 2>/dev/null || { echo "$prog: error: no user for that slot" >&2; exit 2; }
    [ $# -gt 0 ] || { echo "$prog: error: no user for that slot (AUTOGRADER_USERS)" >&2; exit 2; }
    echo "$1"
}

as_user() { # as_user USER COMMAND...: COMMAND as USER, its groups only its own
    u=$1
    shift
    exec setpriv --reuid="$(id -u "$u")" --regid="$(id -g "$u")" --clear-groups "$@"
}

kill_all_of() { # kill_all_of USER: twice, for a process that forked meanwhile
    for _ in 1 2; do
        (as_user "$1" sh -c 'kill -9 -1 2>/dev/null; exit 0') || true
    done
}

[ $# -ge 1 ] || { echo "usage: sandbox.sh run|prepare|cleanup|uid SLOT ..." >&2; exit 2; }
what=$1
shift
case $what in
    run)
        [ $# -ge 3 ] && [ "$2" = -- ] || { echo "usage: sandbox.sh run SLOT -- PROGRAM [ARG...]" >&2; exit 2; }
        u=$(user_of "$1")
        shift 2
        as_user "$u" prlimit --as="${AUTOGRADER_LIMIT_AS:-4294967296}" \
            --nproc="${AUTOGRADER_LIMIT_NPROC:-256}" --fsize="${AUTOGRADER_LIMIT_FSIZE:-268435456}" \
            --core=0 -- \
            env -i PATH=/usr/local/bin:/usr/bin:/bin HOME=/nonexistent LC_ALL=C \
            ${TEST_OUTPUT+"TEST_OUTPUT=$TEST_OUTPUT"} ${TEST_FILTER+"TEST_FILTER=$TEST_FILTER"} \
            ${BIN_DIR+"BIN_DIR=$BIN_DIR"} ${TOOL_DIR+"TOOL_DIR=$TOOL_DIR"} \
            ${GRADE_OBSERVE_FD+"GRADE_OBSERVE_FD=$GRADE_OBSERVE_FD"} "$@" ;;
    prepare)
        [ $# -eq 2 ] || { echo "usage: sandbox.sh prepare SLOT DIR" >&2; exit 2; }
        u=$(user_of "$1")
        chown -R "$(id -u "$u"):$(id -g "$u")" "$2" ;;
    cleanup)
        [ $# -eq 1 ] || { echo "usage: sandbox.sh cleanup SLOT" >&2; exit 2; }
        kill_all_of "$(user_of "$1")" ;;
    cleanup-all)
        for u in $users; do kill_all_of "$u"; done ;;
    uid)
        [ $# -eq 1 ] || { echo "usage: sandbox.sh uid SLOT" >&2; exit 2; }
        id -u "$(user_of "$1")" ;;
    *) echo "$prog: error: unknown command $what" >&2; exit 2 ;;
esac
