// Compiled only by the runner.arrows.forbidden_include_fails_to_compile test, which expects it
// NOT to compile: plan/ may use model/ only, so the scheduler's header is not on its path.
#include "runner/plan/run_plan.h"
#include "runner/schedule/scheduler.h"
