#!/usr/bin/env bash
# test_wedge_parallel.sh - tutorials/wedge Allrun -test -parallel 2 (gates off):
# the checks of test_wedge_case.sh for a decomposed run. About 40 s.
WEDGE_MODE=parallel exec bash "$(dirname "$0")/test_wedge_case.sh"
