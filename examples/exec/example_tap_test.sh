#!/bin/sh
# Any executable is a test case. Its param string is its argv, the suite's environment string
# is in $RTF_ENVIRONMENT, its name in $RTF_TEST_NAME. What it prints as TAP becomes checks;
# without TAP, exit status 0 passes, 77 skips, anything else fails.
#   robottestingframework-testrunner --test example_tap_test.sh -p "--speed 3" -v -d
echo "TAP version 13"
echo "1..3"
echo "# $RTF_TEST_NAME: arguments '$*', environment '$RTF_ENVIRONMENT'"
echo "ok 1 - the shell runs"
if [ -d /tmp ]; then echo "ok 2 - /tmp exists"; else echo "not ok 2 - /tmp exists"; fi
echo "ok 3 - a camera # SKIP no camera on this machine"
