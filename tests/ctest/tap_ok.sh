#!/bin/sh
# An exec test speaking TAP: two checks, both ok.
echo "TAP version 13"
echo "1..2"
echo "ok 1 - the shell runs"
test -n "$0" && echo "ok 2 - it knows its name"
