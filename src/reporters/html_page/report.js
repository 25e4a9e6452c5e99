// The HTML report's page. Everything a test says is data (the JSON above) put in the page with
// textContent only. Rows and details are built when they are shown, so 10 000 tests stay usable.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const page = 200;  // rows built at a time
  const root = document.documentElement;
  const svgNs = "http://www.w3.org/2000/svg";
  const el = (tag, cls, text) => {
    const node = document.createElement(tag);
    if (cls) node.className = cls;
    if (text !== undefined) node.textContent = text;
    return node;
  };
  const svg = (tag, attrs) => {
    const node = document.createElementNS(svgNs, tag);
    for (const key in attrs) node.setAttribute(key, attrs[key]);
    return node;
  };
  // A flaky test (passed on a later attempt) is shown as its own state, under Failing too.
  const failing = (s) => s !== "passed" && s !== "skipped";
  const colour = (s) => s === "passed" ? "passed" : s === "skipped" ? "skipped" :
      s === "flaky" ? "flaky" : s === "interrupted" ? "other" : "failing";
  const secs = (d) => d.toFixed(3) + " s";
  const at = (t) => "+" + t.toFixed(3) + " s";  // from the run's start

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
  const barColour = { passed: "pass", skipped: "skip", other: "other", flaky: "other",
                      failing: "fail" };
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

  // The run's metadata: command line, variables, host, version...
  const facts = document.getElementById("facts");
  for (const [name, value] of data.facts || []) {
    const row = el("tr");
    row.appendChild(el("td", "", name));
    row.appendChild(el("td", "", value));
    facts.appendChild(row);
  }
  if (!facts.firstChild) document.getElementById("run").hidden = true;

  // --- One test's details: a list of sections, each built when the test opens. -------------
  // A section is { name, render(test, suite) -> Node or null }; its node goes in a
  // <div class="section section-NAME">. Other parts of the report (measurements, attachments,
  // history) add their own to testSections, in the order they should show.
  const messageLine = (m) => {
    const line = el("div", m.problem ? "failing" : "");
    if (m.time !== undefined) line.appendChild(el("span", "msg-time", at(m.time)));
    line.appendChild(document.createTextNode(m.label + ": " + m.text +
        (m.at ? "  [" + m.at + "]" : "")));
    // Its diagnostics (a TAP point's YAML keys): a block of their own under the line.
    if (m.diagnostics) line.appendChild(el("pre", "msg-diagnostics", m.diagnostics));
    return line;
  };
  // A test's measurements: a row per name with its last value, its limits, a plot of its values
  // in this run when it has several (repetitions, retries, the same name measured again) and a
  // plot of its values in the last runs (--history). Built when the test opens.
  const limitsText = (m) => m.low !== undefined && m.high !== undefined ?
      "[" + m.low + ", " + m.high + "]" : m.low !== undefined ? ">= " + m.low :
      m.high !== undefined ? "<= " + m.high : "";
  const measurementTable = (t) => {
    const series = new Map();  // name -> [[measurement, label], ...] in the order measured
    const add = (m, label) => {
      if (!series.has(m.name)) series.set(m.name, []);
      series.get(m.name).push([m, label]);
    };
    const attempts = t.attempts || [];
    attempts.forEach((a, i) => {
      for (const m of a.measurements || []) {
        add(m, "attempt " + (i + 1) + (m.rep ? ", repetition " + m.rep : ""));
      }
    });
    for (const m of t.measurements || []) {
      add(m, [attempts.length ? "attempt " + (attempts.length + 1) : "",
               m.rep ? "repetition " + m.rep : ""].filter((x) => x).join(", "));
    }
    const past = (t.history && t.history.measurements) || [];
    for (const h of past) if (!series.has(h.name)) series.set(h.name, []);
    if (!series.size) return null;
    const trends = window.rtfTrends;
    const repeated = [...series.values()].some((values) => values.length > 1);
    const table = el("table", "measures");
    const head = el("tr");
    const columns = ["measurement", "value", "unit", "limits", ""];
    if (repeated) columns.push("this run");
    if (past.length) columns.push("last runs");
    for (const h of columns) head.appendChild(el("th", "", h));
    table.appendChild(head);
    for (const [name, values] of series) {
      const last = values.length ? values[values.length - 1][0] : null;
      const bad = values.filter(([m]) => !m.passed).length;
      const row = el("tr", "measure" + (bad ? " failing" : ""));
      row.dataset.name = name;
      const fromHistory = trends.historySeries(t.history, name);
      const unit = last ? last.unit : fromHistory.unit;
      const cells = [name, last ? String(last.value) + (values.length > 1 ? "  (" + values.length +
                     " values)" : "") : "not measured", unit, last ? limitsText(last) : "",
                     !last ? "" : bad ? (values.length > 1 ? bad + " outside" : "outside") : "ok"];
      for (const v of cells) row.appendChild(el("td", "", v));
      if (repeated) {
        const cell = el("td", "plot");
        if (values.length > 1) {
          cell.appendChild(trends.measurementPlot({ name: name, unit: unit, low: last.low,
              high: last.high, points: values.map(([m, label]) => ({ value: m.value,
                  label: label, outside: !m.passed })) }, "repetitions"));
        }
        row.appendChild(cell);
      }
      if (past.length) {
        const cell = el("td", "plot");
        if (fromHistory) cell.appendChild(trends.measurementPlot(fromHistory, "history"));
        row.appendChild(cell);
      }
      table.appendChild(row);
    }
    return table;
  };
  // Attached files (a test's, or a suite's: its process fixture's logs): links, images inline.
  const attachmentList = (attachments) => {
    if (!attachments || !attachments.length) return null;
    const box = el("div", "attachments");
    for (const a of attachments) {
      const one = el("div", "attached");
      const link = el("a", "", a.name + (a.description ? " \u2014 " + a.description : ""));
      link.href = a.path;
      one.appendChild(link);
      if (/\.(png|jpe?g|svg)$/i.test(a.path)) {
        const img = el("img");
        img.src = a.path;
        img.alt = a.description || a.name;
        one.appendChild(img);
      }
      box.appendChild(one);
    }
    return box;
  };
  const testSections = [
    { name: "identity", render: (t) => {
      const table = el("table");
      const row = (name, value) => {
        if (value === undefined || value === "") return;
        const tr = el("tr");
        tr.appendChild(el("td", "", name));
        const cell = el("td");
        if (value instanceof Node) cell.appendChild(value); else cell.textContent = value;
        tr.appendChild(cell);
        table.appendChild(tr);
      };
      row("id", t.fullId);
      row("name", t.shown);
      if (t.description) row("description", t.description);
      row("type", t.type);
      row("param", t.param);
      if (t.tags && t.tags.length) {
        const tags = el("span");
        for (const tag of t.tags) tags.appendChild(el("span", "tag", tag));
        row("tags", tags);
      }
      row("started", at(t.start));
      row("duration", secs(t.duration));
      return table;
    } },
    { name: "messages", render: (t) => {
      if (!t.messages.length) return null;
      const box = el("div");
      for (const m of t.messages) box.appendChild(messageLine(m));
      return box;
    } },
    { name: "measurements", render: (t) => measurementTable(t) },
    { name: "attachments", render: (t) => attachmentList(t.attachments) },
    { name: "attempts", render: (t) => {
      if (!t.attempts || !t.attempts.length) return null;
      const box = el("div");
      t.attempts.forEach((a, i) => {
        box.appendChild(el("div", colour(a.state), "attempt " + (i + 1) + ": " + a.state +
            " (" + secs(a.duration) + ")" + (a.message ? ": " + a.message : "")));
      });
      return box;
    } },
    { name: "output", render: (t) => {
      if (!t.output) return null;
      const box = el("div");
      box.appendChild(el("div", "note", "output:"));
      box.appendChild(el("pre", "", t.output));
      if (t.outputCut) {
        box.appendChild(el("div", "note", "output cut: " + t.outputCut +
            " more bytes are in the text and JSON outputs"));
      }
      return box;
    } },
  ];
  const fillTest = (box, t, suite) => {
    const detail = el("div", "detail");
    for (const section of testSections) {
      const node = section.render(t, suite);
      if (!node) continue;
      const holder = el("div", "section section-" + section.name);
      holder.appendChild(node);
      detail.appendChild(holder);
    }
    box.appendChild(detail);
  };
  const testRow = (t, suite) => {
    const box = el("details", "test");
    box.dataset.state = t.state;
    const head = el("summary");
    head.appendChild(el("span", "state " + colour(t.state), t.state));
    head.appendChild(el("span", "name", t.shown ? t.name + " (" + t.shown + ")" : t.name));
    for (const tag of t.tags || []) head.appendChild(el("span", "tag", tag));
    if (t.history) head.appendChild(window.rtfTrends.historyStrip(t.history));
    head.appendChild(el("span", "time", secs(t.duration)));
    head.appendChild(el("span", "start", at(t.start)));
    // Why it failed, in the row itself: no click needed.
    if (t.reason) head.appendChild(el("span", "reason", t.reason));
    box.appendChild(head);
    const build = () => {
      if (!box.dataset.built) { box.dataset.built = "1"; fillTest(box, t, suite); }
    };
    // Built as the click opens it (the toggle event comes a task later: until then the row
    // would show nothing); the toggle event still builds what opens otherwise.
    head.addEventListener("click", build);
    box.addEventListener("toggle", () => { if (box.open) build(); });
    if (failing(t.state) && t.state !== "flaky") { build(); box.open = true; }
    return box;
  };

  // --- Which tests show, in which order: the filter, the search box and the sort. -----------
  const filter = document.getElementById("filter");
  const search = document.getElementById("search");
  const sort = document.getElementById("sort");
  for (const t of data.suites.flatMap((s) => s.tests)) {
    t.haystack = [t.name, t.shown || "", t.fullId || "", (t.tags || []).join(" ")]
        .join("\n").toLowerCase();
  }
  const matches = (suite, t) => {
    const f = filter.value;
    if (f === "failing" && !failing(t.state)) return false;
    if ((f === "passed" || f === "skipped") && t.state !== f) return false;
    const q = search.value.trim().toLowerCase();
    return q === "" || t.haystack.includes(q) || suite.name.toLowerCase().includes(q);
  };
  const ordered = (tests) => sort.value === "slowest" ?
      tests.slice().sort((a, b) => b.duration - a.duration) : tests;

  // A suite's rows are built when it opens, a page at a time.
  const fillSuite = (box, suite) => {
    const list = box.querySelector(".tests");
    list.textContent = "";
    if (suite.problems) list.appendChild(el("pre", "failing", suite.problems));
    if (suite.messages.length) {
      const messages = el("div", "suite-messages");
      for (const m of suite.messages) messages.appendChild(messageLine(m));
      list.appendChild(messages);
    }
    if (suite.output) list.appendChild(el("pre", "", suite.output));
    const attached = attachmentList(suite.attachments);
    if (attached) {
      attached.classList.add("suite-attachments");
      list.appendChild(attached);
    }
    const shown = ordered(suite.tests.filter((t) => matches(suite, t)));
    let next = 0;
    const more = el("button", "", "");
    more.type = "button";
    const addPage = () => {
      const end = Math.min(shown.length, next + page);
      for (; next < end; next++) list.insertBefore(testRow(shown[next], suite), more);
      more.textContent = "Show " + Math.min(page, shown.length - next) + " more of " +
          (shown.length - next);
      more.hidden = next >= shown.length;
    };
    more.addEventListener("click", addPage);
    list.appendChild(more);
    addPage();
    box.dataset.built = "1";
  };

  const fixtureTimes = (suite) => {
    const parts = [];
    if (suite.setup > 0.0005) parts.push("setup " + secs(suite.setup));
    if (suite.teardown > 0.0005) parts.push("teardown " + secs(suite.teardown));
    return parts.length ? " (fixture " + parts.join(", ") + ")" : "";
  };

  const suitesBox = document.getElementById("suites");
  const slowest = document.getElementById("slowest");
  const render = () => {
    suitesBox.textContent = "";
    let count = 0;
    const searching = search.value.trim() !== "" || filter.value !== "all";
    const found = [];
    for (const suite of data.suites) {
      const tests = suite.tests.filter((t) => matches(suite, t));
      for (const t of tests) found.push([t, suite]);
      const shown = tests.length;
      if (shown === 0 && !(suite.problems && !searching)) continue;
      count += shown;
      const bad = suite.tests.filter((t) => failing(t.state) && t.state !== "flaky").length;
      const flaky = suite.tests.filter((t) => t.state === "flaky").length;
      const box = el("details", "suite");
      const head = el("summary");
      head.appendChild(el("span", bad || suite.problems ? "failing" : "passed",
          suite.name || "Tests outside any suite"));
      head.appendChild(el("span", "note", "  " + shown + " of " + suite.tests.length + " tests" +
          (bad ? ", " + bad + " failing" : "") + (flaky ? ", " + flaky + " flaky" : "") +
          (suite.problems ? ", fixture failed" : "") + " \u00b7 " + secs(suite.duration) +
          fixtureTimes(suite)));
      box.appendChild(head);
      box.appendChild(el("div", "tests"));
      const buildSuite = () => { if (!box.dataset.built) fillSuite(box, suite); };
      head.addEventListener("click", buildSuite);  // at once, as a test's row (above)
      box.addEventListener("toggle", () => { if (box.open) buildSuite(); });
      suitesBox.appendChild(box);
      // Failures open; so is everything a search or a filter found. Their rows are built
      // now, not on the toggle event, which comes later: what is shown is there at once.
      if (bad || flaky || suite.problems || searching) {
        box.open = true;
        fillSuite(box, suite);
      }
    }
    document.getElementById("shown").textContent = count + " of " + total + " tests shown";
    // The slowest of the tests shown: it follows the filter and the search.
    found.sort((a, b) => b[0].duration - a[0].duration);
    slowest.textContent = "";
    for (const [t, suite] of found.slice(0, 10)) {
      // The id, as --filter takes it and the console prints it.
      slowest.appendChild(el("li", "", secs(t.duration) + "  " +
          (t.fullId || t.name + (suite.name ? "  (" + suite.name + ")" : ""))));
    }
  };
  filter.addEventListener("change", render);
  sort.addEventListener("change", render);
  search.addEventListener("input", render);
  render();

  // --- The timeline: a lane per world shared by suites (<fixture scope="run">: its start,
  // ready, stop, failure), then one lane per suite running at once (-j N), each suite's
  // fixture setup (with the moments its processes were ready), its tests and its teardown.
  // Hover: details.
  const drawTimeline = () => {
    const box = document.getElementById("timeline");
    const suites = data.suites.filter((s) => s.duration > 0 || s.tests.length);
    const worlds = data.worlds || [];
    if (!suites.length && !worlds.length) {
      document.getElementById("timeline-box").hidden = true;
      return;
    }
    // Lanes: each suite its own, labelled by its name. Beyond maxSuiteLanes suites (the chart
    // would be too tall) a suite takes the first lane free when it starts (as the scheduler's
    // slots are), and the lane is labelled by its suites.
    const maxSuiteLanes = 40;
    const lanes = [];      // per lane: when it is free again
    const laneNames = [];  // per lane: the suites in it
    const placed = suites.slice().sort((a, b) => a.start - b.start).map((s) => {
      let lane = suites.length <= maxSuiteLanes ? -1
          : lanes.findIndex((end) => end <= s.start + 1e-4);
      if (lane < 0) { lane = lanes.length; lanes.push(0); laneNames.push([]); }
      lanes[lane] = s.start + s.duration;
      laneNames[lane].push(s.name || "(no suite)");
      return [s, lane];
    });
    const laneLabel = (names) => names[0] + (names.length > 1 ? " +" + (names.length - 1) : "");
    const short = (text) => text.length > 22 ? text.slice(0, 21) + "…" : text;
    const end = Math.max(data.duration, ...suites.map((s) => s.start + s.duration),
                         ...worlds.map((w) => Math.max(w.stop, w.failed, w.ready, w.start)), 1e-3);
    const width = Math.max(box.clientWidth || 900, 600);
    const labels = laneNames.map(laneLabel).concat(worlds.map((w) => w.name));
    const left = Math.min(170, 16 + 6.5 * Math.max(6, ...labels.map((l) => short(l).length)));
    const right = 12, laneHeight = 26;
    const top = 18 + worlds.length * laneHeight;  // the worlds' lanes above the suites'
    const worldTop = 18;
    const scale = (width - left - right) / end;
    const x = (t) => left + t * scale;
    const height = top + lanes.length * laneHeight + 6;
    const chart = svg("svg", { width: width, height: height, role: "img",
                               "aria-label": "timeline of the run" });
    // The time axis: about eight ticks at a round step.
    const raw = end / 8;
    const power = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw);
    const axis = svg("g", { class: "axis" });
    for (let t = 0; t <= end + 1e-9; t += step) {
      axis.appendChild(svg("line", { x1: x(t), x2: x(t), y1: worldTop - 4, y2: height }));
      const label = svg("text", { x: x(t) + 2, y: worldTop - 6 });
      label.textContent = (step < 1 ? t.toFixed(step < 0.1 ? 2 : 1) : t.toFixed(0)) + " s";
      axis.appendChild(label);
    }
    chart.appendChild(axis);
    const titled = (node, text) => {
      const title = svg("title", {});
      title.textContent = text;
      node.appendChild(title);
      return node;
    };
    laneNames.forEach((names, lane) => {
      const label = svg("text", { class: "lane-label suite-lane",
                                  x: 4, y: top + lane * laneHeight + 16 });
      label.textContent = short(laneLabel(names));
      chart.appendChild(titled(label, "suite " + names.join(", then ")));
    });
    const rect = (cls, from, length, y, h, text) => titled(svg("rect", {
      class: cls, x: x(from), y: y, width: Math.max(length * scale, 1), height: h }), text);
    worlds.forEach((w, lane) => {
      const y = worldTop + lane * laneHeight + 3;
      const g = svg("g", { class: "world-bar" });
      g.dataset.world = w.name;
      const name = "world " + w.name + (w.users ? " (shared by " + w.users + ")" : "");
      const label = svg("text", { class: "lane-label world-lane", x: 4, y: y + 13 });
      label.textContent = short(w.name);
      g.appendChild(titled(label, name));
      const upTo = w.ready >= 0 ? w.ready : (w.failed >= 0 ? w.failed : end);
      g.appendChild(titled(svg("rect", { class: "world-starting", x: x(w.start), y: y,
                                         width: Math.max((upTo - w.start) * scale, 1),
                                         height: 20 }),
          name + ": started " + at(w.start) +
          (w.ready >= 0 ? ", ready after " + secs(w.ready - w.start) : "")));
      if (w.ready >= 0) {
        const until = w.stop >= 0 ? w.stop : end;
        g.appendChild(titled(svg("rect", { class: "world-up", x: x(w.ready), y: y + 2,
                                           width: Math.max((until - w.ready) * scale, 1),
                                           height: 16 }),
            name + ": ready " + at(w.ready) +
            (w.stop >= 0 ? ", stopped " + at(w.stop) + " (up " + secs(w.stop - w.start) + ")"
                         : "")));
        g.appendChild(titled(svg("line", { class: "ready", x1: x(w.ready), x2: x(w.ready),
                                          y1: y, y2: y + 20 }), name + ": ready " + at(w.ready)));
      }
      if (w.failed >= 0) {
        g.appendChild(titled(svg("rect", { class: "world-failed t-failing", x: x(w.failed) - 2,
                                           y: y, width: 4, height: 20 }),
            name + ": " + (w.ready >= 0 ? "collapsed " : "failed to start ") + at(w.failed) +
            (w.reason ? "\n" + w.reason : "")));
      }
      const text = svg("text", { class: "suite-label", x: x(w.start) + 3, y: y + 14 });
      text.textContent = w.name;
      g.appendChild(text);
      chart.appendChild(g);
    });
    // Every test drawn while that stays cheap; beyond, each suite's tests as one bar.
    const eachTest = data.counts.total <= 3000;
    for (const [s, lane] of placed) {
      const y = top + lane * laneHeight + 3;
      const g = svg("g", { class: "suite-bar" });
      g.dataset.suite = s.name;
      const name = s.name || "tests outside any suite";
      if (s.setup > 0) {
        g.appendChild(rect("setup", s.start, s.setup, y, 20,
            name + ": fixture setup " + secs(s.setup) + " (from " + at(s.start) + ")"));
      }
      const ready = s.messages.filter((m) => m.time <= s.start + s.setup + 1e-6 &&
                                            /ready/.test(m.text));
      for (const m of ready) {
        g.appendChild(titled(svg("line", { class: "ready", x1: x(m.time), x2: x(m.time),
                                          y1: y, y2: y + 20 }),
            name + ": " + m.text + " (" + at(m.time) + ")"));
      }
      if (eachTest) {
        for (const t of s.tests) {
          if (t.duration <= 0 && t.state === "skipped") continue;
          const text = name + " / " + t.name + ": " + t.state + ", " + secs(t.duration) +
              " from " + at(t.start) + (t.reason ? "\n" + t.reason : "");
          const bar = rect("test t-" + colour(t.state), t.start, t.duration, y + 2, 16, text);
          if (colour(t.state) === "failing") {
            // A failure stays visible beside long tests: at least 4 px wide, and a marker
            // above it.
            const shown = Math.max(t.duration * scale, 4);
            bar.setAttribute("width", shown);
            const mid = x(t.start) + shown / 2;
            const marker = titled(svg("path", { class: "failure-marker",
                d: `M${mid - 4},${y - 3} L${mid + 4},${y - 3} L${mid},${y + 3} Z` }), text);
            marker.dataset.test = t.name;
            g.appendChild(bar);
            g.appendChild(marker);
            continue;
          }
          g.appendChild(bar);
        }
      } else if (s.tests.length) {
        const from = s.start + s.setup;
        const length = s.duration - s.setup - s.teardown;
        g.appendChild(rect("tests", from, length, y + 2, 16,
            name + ": " + s.tests.length + " tests, " + secs(length)));
      }
      if (s.teardown > 0) {
        g.appendChild(rect("teardown", s.start + s.duration - s.teardown, s.teardown, y, 20,
            name + ": fixture teardown " + secs(s.teardown)));
      }
      chart.appendChild(g);
    }
    box.appendChild(chart);
  };
  drawTimeline();
})();
