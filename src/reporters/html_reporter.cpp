#include "reporters/html_reporter.h"

#include <chrono>
#include <cstdio>
#include <ctime>

#include "reporters/summary.h"
#include "reporters/text_safety.h"

namespace robottestingframework {
namespace reporters {

namespace {

using Kind = ResultEvent::Kind;

// No network at all, and no script but the page's own.
const char* const head = R"html(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data: 'self' file:">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Robot Testing Framework results</title>
<style>
:root { --bg: #ffffff; --fg: #1f2328; --muted: #656d76; --line: #d0d7de; --panel: #f6f8fa;
  --pass: #1a7f37; --fail: #cf222e; --skip: #9a6700; --other: #8250df; }
:root[data-theme="dark"] { --bg: #0d1117; --fg: #e6edf3; --muted: #8d96a0; --line: #30363d;
  --panel: #161b22; --pass: #3fb950; --fail: #f85149; --skip: #d29922; --other: #a371f7; }
* { box-sizing: border-box; }
body { margin: 0; padding: 1.5rem; font: 14px/1.45 system-ui, sans-serif; background: var(--bg);
  color: var(--fg); }
h1 { font-size: 1.4rem; margin: 0 0 .5rem; } h2 { font-size: 1.1rem; margin: 1.2rem 0 .5rem; }
header { display: flex; flex-wrap: wrap; gap: 1rem; align-items: baseline; }
#theme { margin-left: auto; }
button, input, select { font: inherit; color: var(--fg); background: var(--panel);
  border: 1px solid var(--line); border-radius: 6px; padding: .25rem .6rem; }
#counts span { margin-right: 1rem; }
#bar { display: flex; height: 12px; border-radius: 6px; overflow: hidden; background: var(--line);
  margin: .6rem 0 1rem; }
#bar div { height: 100%; }
.passed { color: var(--pass); } .failing { color: var(--fail); } .skipped { color: var(--skip); }
.other { color: var(--other); }
#controls { display: flex; gap: .5rem; flex-wrap: wrap; margin-bottom: 1rem; }
#search { min-width: 18rem; }
details.suite { border: 1px solid var(--line); border-radius: 6px; margin: .4rem 0;
  background: var(--panel); }
details.suite > summary { cursor: pointer; padding: .4rem .6rem; font-weight: 600; }
.tests { background: var(--bg); border-top: 1px solid var(--line); }
.test > summary { cursor: pointer; padding: .2rem .6rem; list-style: none; display: flex;
  gap: .6rem; }
.test > summary::before { content: "\25B8"; color: var(--muted); }
.test[open] > summary::before { content: "\25BE"; }
.state { min-width: 6.5rem; font-weight: 600; }
.time, .note { color: var(--muted); }
.time { margin-left: auto; }
.detail { padding: .2rem 1rem .6rem 2.2rem; }
.detail div { white-space: pre-wrap; word-break: break-word; }
.measures { border-collapse: collapse; margin: .3rem 0; }
.measures td, .measures th { padding: .1rem .6rem; text-align: left; }
.attached img { max-width: 32rem; max-height: 20rem; display: block; }
pre { background: var(--panel); border: 1px solid var(--line); border-radius: 6px; padding: .5rem;
  white-space: pre-wrap; word-break: break-word; margin: .3rem 0; }
#slowest li { margin: .1rem 0; }
</style>
</head>
<body>
<header><h1>Robot Testing Framework results</h1><span id="when" class="note"></span>
<button id="theme" type="button">Dark theme</button></header>
<div id="counts"></div>
<div id="bar" role="img" aria-label="passed and failed tests"></div>
<div id="controls">
<select id="filter" aria-label="Show tests">
<option value="all">All tests</option><option value="failing">Failing</option>
<option value="passed">Passed</option><option value="skipped">Skipped</option>
</select>
<input id="search" type="search" placeholder="Search tests and suites" aria-label="Search">
<span id="shown" class="note"></span>
</div>
<div id="suites"></div>
<h2>Slowest tests</h2>
<ol id="slowest"></ol>
<script type="application/json" id="report-data">)html";

const char* const tail = R"html(</script>
<script>
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const page = 200;  // rows built at a time
  const root = document.documentElement;
  const el = (tag, cls, text) => {
    const node = document.createElement(tag);
    if (cls) node.className = cls;
    if (text !== undefined) node.textContent = text;
    return node;
  };
  const failing = (s) => s !== "passed" && s !== "skipped" && s !== "flaky";
  const colour = (s) => s === "passed" ? "passed" : s === "skipped" ? "skipped" :
      s === "interrupted" || s === "flaky" ? "other" : "failing";
  const secs = (d) => d.toFixed(3) + " s";

  // Theme: the system's unless chosen.
  let dark = window.matchMedia && window.matchMedia("(prefers-color-scheme: dark)").matches;
  const theme = document.getElementById("theme");
  const applyTheme = () => {
    root.dataset.theme = dark ? "dark" : "light";
    theme.textContent = dark ? "Light theme" : "Dark theme";
  };
  theme.addEventListener("click", () => { dark = !dark; applyTheme(); });
  applyTheme();

  // Summary and bar.
  document.getElementById("when").textContent = data.started + " \u00b7 " + secs(data.duration);
  const counts = document.getElementById("counts");
  const order = ["passed", "flaky", "failed", "error", "crashed", "timed out", "interrupted",
                 "skipped"];
  const total = data.counts.total;
  counts.appendChild(el("span", "", total + " tests"));
  const bar = document.getElementById("bar");
  const barColour = { passed: "pass", skipped: "skip", other: "other", failing: "fail" };
  for (const state of order) {
    const n = data.counts[state] || 0;
    if (n === 0 && state !== "passed" && state !== "failed") continue;
    counts.appendChild(el("span", colour(state), n + " " + state));
    if (n > 0 && total > 0) {
      const part = el("div");
      part.style.width = (100 * n / total) + "%";
      part.style.background = "var(--" + barColour[colour(state)] + ")";
      part.title = n + " " + state;
      bar.appendChild(part);
    }
  }
  counts.appendChild(el("span", "", data.suitesRun + " suites, " + data.suitesFailed + " failed"));

  // One test's details, built when it is opened.
  const fillTest = (box, t) => {
    const detail = el("div", "detail");
    if (t.description) detail.appendChild(el("div", "note", t.description));
    for (const m of t.messages) {
      const line = el("div", m.problem ? "failing" : "");
      line.textContent = m.label + ": " + m.text + (m.at ? "  [" + m.at + "]" : "");
      detail.appendChild(line);
    }
    if (t.measurements && t.measurements.length) {
      const table = el("table", "measures");
      const head = el("tr");
      for (const h of ["measurement", "value", "unit", "limits", ""]) head.appendChild(el("th", "", h));
      table.appendChild(head);
      for (const m of t.measurements) {
        const row = el("tr", m.passed ? "" : "failing");
        const limits = m.low !== undefined && m.high !== undefined ? "[" + m.low + ", " + m.high + "]"
            : m.low !== undefined ? ">= " + m.low : m.high !== undefined ? "<= " + m.high : "";
        for (const v of [m.name + (m.rep ? " #" + m.rep : ""), String(m.value), m.unit, limits,
                         m.passed ? "ok" : "outside"]) row.appendChild(el("td", "", v));
        table.appendChild(row);
      }
      detail.appendChild(table);
    }
    for (const a of t.attachments || []) {
      const box = el("div", "attached");
      const link = el("a", "", a.name + (a.description ? " \u2014 " + a.description : ""));
      link.href = a.path;
      box.appendChild(link);
      if (/\.(png|jpe?g|svg)$/i.test(a.path)) {
        const img = el("img");
        img.src = a.path;
        img.alt = a.description || a.name;
        box.appendChild(img);
      }
      detail.appendChild(box);
    }
    if (t.output) {
      detail.appendChild(el("div", "note", "output:"));
      detail.appendChild(el("pre", "", t.output));
      if (t.outputCut) {
        detail.appendChild(el("div", "note", "output cut: " + t.outputCut +
            " more bytes are in the text and JSON outputs"));
      }
    }
    if (!detail.firstChild) detail.appendChild(el("div", "note", "nothing reported"));
    box.appendChild(detail);
  };
  const testRow = (t) => {
    const box = el("details", "test");
    const head = el("summary");
    head.appendChild(el("span", "state " + colour(t.state), t.state));
    head.appendChild(el("span", "name", t.shown ? t.name + " (" + t.shown + ")" : t.name));
    head.appendChild(el("span", "time", secs(t.duration)));
    box.appendChild(head);
    box.addEventListener("toggle", () => {
      if (box.open && !box.dataset.built) { box.dataset.built = "1"; fillTest(box, t); }
    });
    return box;
  };

  // Which tests show: the filter and the search box.
  const filter = document.getElementById("filter");
  const search = document.getElementById("search");
  const matches = (suite, t) => {
    const f = filter.value;
    if (f === "failing" && !failing(t.state)) return false;
    if ((f === "passed" || f === "skipped") && t.state !== f) return false;
    const q = search.value.trim().toLowerCase();
    return q === "" || t.name.toLowerCase().includes(q) || suite.name.toLowerCase().includes(q);
  };

  // A suite's rows are built when it opens, a page at a time.
  const fillSuite = (box, suite) => {
    const list = box.querySelector(".tests");
    list.textContent = "";
    if (suite.problems) list.appendChild(el("pre", "failing", suite.problems));
    if (suite.output) list.appendChild(el("pre", "", suite.output));
    const shown = suite.tests.filter((t) => matches(suite, t));
    let next = 0;
    const more = el("button", "", "");
    more.type = "button";
    const addPage = () => {
      const end = Math.min(shown.length, next + page);
      for (; next < end; next++) list.insertBefore(testRow(shown[next]), more);
      more.textContent = "Show " + Math.min(page, shown.length - next) + " more of " +
          (shown.length - next);
      more.hidden = next >= shown.length;
    };
    more.addEventListener("click", addPage);
    list.appendChild(more);
    addPage();
    box.dataset.built = "1";
  };

  const suitesBox = document.getElementById("suites");
  const render = () => {
    suitesBox.textContent = "";
    let count = 0;
    const searching = search.value.trim() !== "" || filter.value !== "all";
    for (const suite of data.suites) {
      const shown = suite.tests.filter((t) => matches(suite, t)).length;
      if (shown === 0 && !(suite.problems && !searching)) continue;
      count += shown;
      const bad = suite.tests.filter((t) => failing(t.state)).length;
      const box = el("details", "suite");
      const head = el("summary");
      head.appendChild(el("span", bad || suite.problems ? "failing" : "passed",
          suite.name || "Tests outside any suite"));
      head.appendChild(el("span", "note", "  " + shown + " of " + suite.tests.length + " tests" +
          (bad ? ", " + bad + " failing" : "") + (suite.problems ? ", fixture failed" : "") +
          " \u00b7 " + secs(suite.duration)));
      box.appendChild(head);
      box.appendChild(el("div", "tests"));
      box.addEventListener("toggle", () => {
        if (box.open && !box.dataset.built) fillSuite(box, suite);
      });
      suitesBox.appendChild(box);
      // Failures open; so is everything a search or a filter found.
      if (bad || suite.problems || searching) box.open = true;
    }
    document.getElementById("shown").textContent = count + " of " + total + " tests shown";
  };
  filter.addEventListener("change", render);
  search.addEventListener("input", render);
  render();

  // The slowest tests.
  const all = [];
  for (const suite of data.suites) for (const t of suite.tests) all.push([t, suite]);
  all.sort((a, b) => b[0].duration - a[0].duration);
  const slowest = document.getElementById("slowest");
  for (const [t, suite] of all.slice(0, 10)) {
    slowest.appendChild(el("li", "", secs(t.duration) + "  " + t.name +
        (suite.name ? "  (" + suite.name + ")" : "")));
  }
})();
</script>
</body>
</html>
)html";

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6f", value);
    return text;
}

const char* label(const ResultEvent& event) {
    return event.kind == Kind::Check && !event.passed ? "check failed" : toString(event.kind);
}

// The message as the page shows it, the place it came from apart.
std::string messageData(const ResultEvent& event) {
    const TestMessage& msg = event.message;
    std::string text = msg.getMessage();
    if (!msg.getDetail().empty()) {
        text += ": " + msg.getDetail();
    }
    std::string out = "{\"label\":" + jsonString(label(event)) + ",\"text\":" + jsonString(text);
    if (!msg.getSourceFileName().empty()) {
        out += ",\"at\":" + jsonString(msg.getSourceFileName() + ":" +
                                       std::to_string(msg.getSourceLineNumber()));
    }
    if (isFailure(stateOf(event.kind)) || (event.kind == Kind::Check && !event.passed)) {
        out += ",\"problem\":true";
    }
    return out + "}";
}

// A test's measurements (a table on the page) and attachments (links; images inline).
void appendMeasurementsAndAttachments(std::string& out, const std::vector<ResultEvent>& events) {
    std::string measurements;
    std::string attachments;
    for (const ResultEvent& event : events) {
        if (event.kind == Kind::Measurement && event.measurement) {
            const Measurement& m = *event.measurement;
            measurements +=
                std::string(measurements.empty() ? "" : ",") + "{\"name\":" + jsonString(m.name) +
                ",\"value\":" + formatNumber(m.value) + ",\"unit\":" + jsonString(m.unit);
            if (m.low) {
                measurements += ",\"low\":" + formatNumber(*m.low);
            }
            if (m.high) {
                measurements += ",\"high\":" + formatNumber(*m.high);
            }
            measurements += std::string(",\"passed\":") + (event.passed ? "true" : "false") +
                            ",\"rep\":" + std::to_string(event.repetition) + "}";
        } else if (event.kind == Kind::Attachment && event.attachment) {
            const Attachment& a = *event.attachment;
            attachments += std::string(attachments.empty() ? "" : ",") +
                           "{\"name\":" + jsonString(a.originalName) +
                           ",\"path\":" + jsonString(a.path) +
                           ",\"description\":" + jsonString(a.description) +
                           ",\"size\":" + std::to_string(a.size) + "}";
        }
    }
    if (!measurements.empty()) {
        out += ",\"measurements\":[" + measurements + "]";
    }
    if (!attachments.empty()) {
        out += ",\"attachments\":[" + attachments + "]";
    }
}

// Cut on a character boundary, never inside a UTF-8 sequence.
std::string capped(const std::string& text, std::size_t& cut) {
    const std::string valid = validUtf8(text);
    if (valid.size() <= HtmlReporter::outputCap) {
        cut = 0;
        return valid;
    }
    std::size_t end = HtmlReporter::outputCap;
    while (end > 0 && (static_cast<unsigned char>(valid[end]) & 0xC0) == 0x80) {
        --end;
    }
    cut = valid.size() - end;
    return valid.substr(0, end);
}

}  // namespace

std::string HtmlReporter::document() {
    const std::time_t started = std::chrono::system_clock::to_time_t(collector_.startedAt());
    std::tm utc{};
    gmtime_r(&started, &utc);
    char when[40];
    std::strftime(when, sizeof(when), "%Y-%m-%d %H:%M:%S UTC", &utc);

    std::string out = head;
    out += "{\"started\":" + jsonString(when);
    out += ",\"duration\":" + number(collector_.duration());
    out += ",\"suitesRun\":" + std::to_string(collector_.suiteCount());
    out += ",\"suitesFailed\":" + std::to_string(collector_.failedSuiteCount());
    out += ",\"counts\":{\"total\":" + std::to_string(collector_.testCount());
    for (TestStatus status :
         {TestStatus::Passed, TestStatus::Skipped, TestStatus::Failed, TestStatus::Error,
          TestStatus::Crashed, TestStatus::TimedOut, TestStatus::Interrupted, TestStatus::Flaky}) {
        out +=
            "," + jsonString(toString(status)) + ":" + std::to_string(collector_.countOf(status));
    }
    out += "},\"suites\":[";
    bool firstSuite = true;
    for (const SuiteRecord& suite : collector_.suites()) {
        out += firstSuite ? "\n" : ",\n";
        firstSuite = false;
        std::size_t cut = 0;
        out += "{\"name\":" + jsonString(suite.name) + ",\"duration\":" + number(suite.duration);
        if (suite.fixtureFailed) {
            out += ",\"problems\":" + jsonString(traceText(suite.events));
        }
        if (!suite.output.empty()) {
            out += ",\"output\":" + jsonString(capped(suite.output, cut));
        }
        out += ",\"tests\":[";
        bool firstTest = true;
        for (const TestRecord& test : suite.tests) {
            out += firstTest ? "\n" : ",\n";
            firstTest = false;
            out += "{\"id\":" + std::to_string(test.id);
            // The name is its id in its suite; "shown" the name it gave itself, beside it.
            const std::string& name = test.reportName();
            out += ",\"name\":" + jsonString(name.empty() ? "unnamed test" : name);
            if (!test.shownName().empty()) {
                out += ",\"shown\":" + jsonString(test.shownName());
            }
            out += ",\"state\":" + jsonString(toString(test.status));
            out += ",\"duration\":" + number(test.duration);
            if (!test.description.empty()) {
                out += ",\"description\":" + jsonString(test.description);
            }
            out += ",\"messages\":[";
            bool firstMessage = true;
            for (const ResultEvent& event : test.events) {
                if (event.kind == Kind::Measurement || event.kind == Kind::Attachment) {
                    continue;  // in their own table and links below
                }
                if (!settings_.verbose &&
                    (event.kind == Kind::Report || event.kind == Kind::Check) &&
                    !(event.kind == Kind::Check && !event.passed)) {
                    continue;
                }
                out += (firstMessage ? "" : ",") + messageData(event);
                firstMessage = false;
            }
            out += "]";
            appendMeasurementsAndAttachments(out, test.events);
            if (!test.output.empty()) {
                out += ",\"output\":" + jsonString(capped(test.output, cut));
                if (cut > 0) {
                    out += ",\"outputCut\":" + std::to_string(cut);
                }
            }
            out += "}";
        }
        out += "]}";
    }
    out += "]}";
    out += tail;
    return out;
}

}  // namespace reporters
}  // namespace robottestingframework
