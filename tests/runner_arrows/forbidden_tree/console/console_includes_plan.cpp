// Read (never compiled) by the runner.arrows.check_rejects test: console/ may use schedule/ and
// model/; plan/'s headers reach it through the scheduler's, but it may not include them itself.
#include "runner/plan/run_plan.h"
