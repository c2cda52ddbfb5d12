#!/usr/bin/env bash
# test_wedge_steady.sh - tutorials/wedge Allrun -steady -test (the frozen-RANS
# route, gates off): the checks of test_wedge_case.sh, and the tracer-limit check on
# its flow. About 1 min.
WEDGE_MODE=steady exec bash "$(dirname "$0")/test_wedge_case.sh"
