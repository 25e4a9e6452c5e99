#include "reporters/history_strip.h"

#include <cstdio>

#include "reporters/text_safety.h"

namespace robottestingframework {
namespace reporters {

std::string historyStripData(const HistoryStrip& strip) {
    std::string out = "{\"states\":[";
    for (std::size_t i = 0; i < strip.states.size(); ++i) {
        out += (i == 0 ? "" : ",") + jsonString(strip.states[i]);
    }
    out += "],\"durations\":[";
    char number[32];
    for (std::size_t i = 0; i < strip.durations.size(); ++i) {
        std::snprintf(number, sizeof(number), "%.6f", strip.durations[i]);
        out += (i == 0 ? "" : ",") + std::string(number);
    }
    std::snprintf(number, sizeof(number), "%.4f", strip.flakyRate);
    return out + "],\"flakyRate\":" + number + "}";
}

// SVG built with createElementNS (no markup from data), coloured by the report's own variables.
const char* historyStripScript() {
    return R"html(<style>
.history { display: inline-flex; gap: .4rem; align-items: center; }
.history .cells { display: inline-flex; gap: 1px; }
.history .cell { width: 6px; height: 12px; border-radius: 1px; background: var(--line); }
.history .cell.passed { background: var(--pass); } .history .cell.failing { background: var(--fail); }
.history .cell.skipped { background: var(--skip); } .history .cell.other { background: var(--other); }
.history svg { width: 60px; height: 14px; }
.history polyline { fill: none; stroke: var(--muted); stroke-width: 1.2; }
</style>
<script>
"use strict";
window.rtfHistoryStrip = function (history) {
  const kind = (s) => s === "passed" ? "passed" : s === "skipped" ? "skipped" :
      s === "interrupted" || s === "flaky" ? "other" : "failing";
  const box = document.createElement("span");
  box.className = "history";
  box.title = "last " + history.states.length + " runs";
  const cells = document.createElement("span");
  cells.className = "cells";
  history.states.forEach((s, i) => {
    const cell = document.createElement("span");
    cell.className = "cell " + kind(s);
    cell.title = s + " (" + history.durations[i].toFixed(3) + " s)";
    cells.appendChild(cell);
  });
  box.appendChild(cells);
  const d = history.durations;
  if (d.length > 1) {
    const ns = "http://www.w3.org/2000/svg";
    const svg = document.createElementNS(ns, "svg");
    svg.setAttribute("viewBox", "0 0 60 14");
    svg.setAttribute("class", "sparkline");
    const top = Math.max(...d) || 1;
    const line = document.createElementNS(ns, "polyline");
    line.setAttribute("points", d.map((v, i) =>
        (60 * i / (d.length - 1)).toFixed(1) + "," + (13 - 12 * v / top).toFixed(1)).join(" "));
    svg.appendChild(line);
    box.appendChild(svg);
  }
  const rate = document.createElement("span");
  rate.className = "note flaky-rate";
  rate.textContent = "flaky " + Math.round(100 * history.flakyRate) + "%";
  box.appendChild(rate);
  return box;
};
</script>
)html";
}

}  // namespace reporters
}  // namespace robottestingframework
