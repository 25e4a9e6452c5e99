// The build folder's paths the unit tests read and write. Their values live in one source file
// generated per build (rtf_build_paths in build_paths.cmake), not in compile definitions, so the
// test sources compile the same in every build folder and ccache shares them between the
// main, portable-POSIX and later builds. A target defines only the paths it needs.
#pragma once

namespace build_paths {

const char* unitTestTmpDir();    // scratch files of the tests, under the build tree
const char* testPluginDir();     // the test plug-ins (tests/plugins) as built
const char* junitSchema();       // schemas/junit.xsd of the source tree
const char* tapCorpusDir();      // tests/unit/tap of the source tree
const char* workerPath();        // robottestingframework-worker as built
const char* windowsPluginDir();  // the Windows build's test plug-ins and programs

}  // namespace build_paths
