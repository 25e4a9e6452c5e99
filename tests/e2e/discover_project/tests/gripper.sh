#!/bin/sh
# A test beside the suites folder (suites/beside.xml names it ../tests/gripper.sh).
exit 0
