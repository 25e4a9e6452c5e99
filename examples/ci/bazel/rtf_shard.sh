#!/bin/sh
# The sh_test of BUILD: one shard of the suites in the folder $1. The runner reads Bazel's shard
# variables itself and writes its JUnit report where Bazel collects it (XML_OUTPUT_FILE).
exec robottestingframework-testrunner --suites "$1" --no-output
