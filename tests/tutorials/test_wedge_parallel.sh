#!/usr/bin/env bash
# test_wedge_parallel.sh - tutorials/wedge Allrun -test serially and with -parallel 2
# (transient route, gates off): the checks of test_wedge_case.sh for both, and
# their nose impact counts within 4 Poisson standard deviations. About 60 s.
WEDGE_MODE=parallel exec bash "$(dirname "$0")/test_wedge_case.sh"
