#!/bin/sh
# Says it runs (creates $1), then waits until it is stopped.
touch "$1"
exec sleep 120
