// The live page: a snapshot of the run, then its changes as Server-Sent Events. Everything a
// test says is put in the page as text (textContent), never as HTML.
"use strict";

const run = { state: "waiting", tests: 0, passed: 0, failed: 0, skipped: 0, duration: 0 };
const suites = [];
// The worlds shared by suites (<fixture scope="run">), each a lane: its state and times.
const worlds = [];
let worldsDirty = true;
let lastSeq = 0;
let source = null;
let drawPending = false;
// The run view's clock ("now" of the snapshot and of each change) less this page's: running
// tests and suites tick their elapsed time from when they started on it.
let clockOffset = null;

function setClock(now) {
  if (typeof now === "number") clockOffset = now - performance.now() / 1000;
}

function elapsedSince(startedAt) {
  if (clockOffset === null || typeof startedAt !== "number") return 0;
  return Math.max(0, performance.now() / 1000 + clockOffset - startedAt);
}

// A ticking "running 1.2 s": its text is redrawn by tick() until the change that ends it.
function elapsedNode(tag, className, startedAt, what) {
  const node = element(tag, className + " elapsed");
  node.dataset.startedAt = startedAt;
  node.dataset.what = what;
  node.textContent = what + " " + seconds(elapsedSince(startedAt));
  return node;
}

function tick() {
  for (const node of document.querySelectorAll(".elapsed")) {
    node.textContent = node.dataset.what + " " +
        seconds(elapsedSince(Number(node.dataset.startedAt)));
  }
}
setInterval(tick, 200);

function element(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

function stateClass(state) {
  return "state state-" + String(state).replace(/ /g, "-");
}

function seconds(value) {
  return (Number(value) || 0).toFixed(3) + " s";
}

function messagesList(messages, hidden) {
  const list = element("ul", "messages");
  for (const message of messages || []) {
    const item = element("li");
    item.appendChild(element("span", "kind", message.kind + ":"));
    item.appendChild(document.createTextNode(message.text));
    if (message.where) item.appendChild(element("span", "where", "[" + message.where + "]"));
    // Its diagnostics (a TAP point's YAML keys): a block of their own under the line.
    if (message.diagnostics) item.appendChild(element("pre", "diagnostics", message.diagnostics));
    list.appendChild(item);
  }
  if (hidden > 0) {
    list.appendChild(element("li", "hidden", "… " + hidden + " more messages (the result files have them)"));
  }
  return list;
}

// Each measurement of the test: its latest value and a plot of its values in the last runs
// (--history) followed by this run's, ringed. Only for tests that measured something, now or
// in the history.
function measurementsTable(test) {
  const now = new Map();  // name -> this run's values, in the order measured
  for (const m of test.measurements || []) {
    if (!now.has(m.name)) now.set(m.name, []);
    now.get(m.name).push(m);
  }
  const past = (test.history && test.history.measurements) || [];
  for (const h of past) if (!now.has(h.name)) now.set(h.name, []);
  if (!now.size) return null;
  const trends = window.rtfTrends;
  const table = element("table", "measures");
  for (const [name, values] of now) {
    const last = values[values.length - 1];
    const history = trends.historySeries(test.history, name);
    const row = element("tr", "measure" + (values.some((m) => !m.passed) ? " state-failed" : ""));
    row.dataset.name = name;
    const unit = last ? last.unit : history.unit;
    row.appendChild(element("td", "measure-name", name));
    row.appendChild(element("td", "measure-value", last ? last.value + (unit ? " " + unit : "")
        : "not measured yet"));
    const plot = element("td", "plot");
    const points = (history ? history.points : []).concat(values.map((m) => ({
      value: m.value, current: true, outside: !m.passed, label: "this run" })));
    if (points.length > 1) {
      plot.appendChild(trends.measurementPlot({ name: name, unit: unit,
          low: last ? last.low : history.low, high: last ? last.high : history.high,
          points: points }, "history"));
    }
    row.appendChild(plot);
    table.appendChild(row);
  }
  return table;
}

function testRow(test) {
  const row = element("tr", "test");
  row.dataset.state = test.state;
  row.appendChild(element("td", stateClass(test.state), test.state));
  const name = element("td", "name");
  name.appendChild(element("span", "test-name", test.name));
  // --history: its recent runs (trends.js, as the HTML report draws them).
  if (test.history) name.appendChild(window.rtfTrends.historyStrip(test.history));
  const measured = measurementsTable(test);
  if (measured) name.appendChild(measured);
  if ((test.messages && test.messages.length) || test.hiddenReports > 0) {
    name.appendChild(messagesList(test.messages, test.hiddenReports));
  }
  if (test.output) name.appendChild(element("pre", "output", test.output));
  row.appendChild(name);
  if (test.state === "running") {
    row.appendChild(elapsedNode("td", "duration", test.startedAt, "running"));
  } else {
    row.appendChild(element("td", "duration", test.state === "not run" ? "" : seconds(test.duration)));
  }
  return row;
}

function suiteTitle(suite) {
  const title = element("h2");
  title.appendChild(element("span", stateClass(suite.state), suite.state));
  title.appendChild(document.createTextNode(" "));
  title.appendChild(element("span", "suite-name", suite.name));
  if (suite.state === "waiting") {
    // Planned, not started yet (another suite runs first, or beside it with -j N).
    title.appendChild(element("span", "where", "not started"));
  } else if (suite.state !== "running") {
    title.appendChild(element("span", "where", seconds(suite.duration)));
  } else {
    // Before its first test the fixture sets up; after its last one it tears down.
    const tests = suite.tests || [];
    const phase = tests.length && tests.every((t) => t.state === "not run") ? "fixture setting up, "
        : tests.length && tests.every((t) => t.state !== "not run" && t.state !== "running")
        ? "fixture tearing down, " : "";
    title.appendChild(elapsedNode("span", "where", suite.startedAt, phase + "running"));
  }
  return title;
}

function suiteSection(suite) {
  const section = element("section", "suite");
  section.dataset.state = suite.state;
  const title = suiteTitle(suite);
  section.appendChild(title);
  if ((suite.messages && suite.messages.length) || suite.hiddenReports > 0) {
    section.appendChild(messagesList(suite.messages, suite.hiddenReports));
  }
  const table = element("table");
  for (const test of suite.tests || []) table.appendChild(testRow(test));
  section.appendChild(table);
  return section;
}

// The run's attachments, linked once it has ended (README: Attachments).
function drawAttachments() {
  const old = document.getElementById("attachments");
  if (old) old.remove();
  if (!run.attachments || run.attachments.length === 0) return;
  const box = element("section", "attachments");
  box.id = "attachments";
  box.appendChild(element("h2", "", "Attachments"));
  const list = element("ul");
  for (const attachment of run.attachments) {
    const item = element("li");
    const link = element("a", "", attachment.name);
    link.href = attachment.url;
    item.appendChild(link);
    item.appendChild(element("span", "where", " " + attachment.test +
        (attachment.description ? " \u2014 " + attachment.description : "")));
    list.appendChild(item);
  }
  box.appendChild(list);
  document.querySelector("header").appendChild(box);
}

function drawSummary() {
  const summary = document.getElementById("summary");
  const counts = run.passed + " passed, " + run.failed + " failed, " + run.skipped +
      " skipped of " + run.tests;
  if (run.state === "finished") {
    summary.textContent = "Finished: " + counts + " in " + seconds(run.duration);
    summary.className = "summary finished " + (run.failed > 0 ? "state-failed" : "state-passed");
  } else if (run.state === "running") {
    summary.textContent = "Running: " + counts;
    summary.className = "summary running state-running";
  } else {
    summary.textContent = "Waiting for the run…";
    summary.className = "summary waiting";
  }
  drawAttachments();
  const total = Math.max(run.tests, 1);
  document.getElementById("bar-passed").style.width = (100 * run.passed / total) + "%";
  document.getElementById("bar-failed").style.width = (100 * run.failed / total) + "%";
  document.getElementById("bar-skipped").style.width = (100 * run.skipped / total) + "%";
}

// A shared world's lane: its name, state, how many suites share it, a bar of its start (grey)
// and its time up (green; red when it failed or collapsed), and its times in words.
function worldLane(world) {
  const lane = element("div", "world world-" + world.state);
  lane.dataset.world = world.name;
  const title = element("h2");
  title.appendChild(element("span", "world-name", "world " + world.name));
  title.appendChild(element("span", stateClass(world.state), world.state));
  if (world.users) title.appendChild(element("span", "world-users", "shared by " + world.users));
  lane.appendChild(title);
  const ready = world.readyAt >= 0 ? world.readyAt : null;
  const stopped = world.stoppedAt >= 0 ? world.stoppedAt : null;
  const starting = (ready !== null ? ready : (stopped !== null ? stopped : null));
  const bar = element("div", "world-bar");
  const total = Math.max(1e-3, (stopped !== null ? stopped : Math.max(ready || 0,
      world.startedAt + elapsedSince(world.startedAt))) - world.startedAt);
  const part = (cls, length, text) => {
    const span = element("span", cls);
    span.style.width = Math.max(0.5, 100 * length / total) + "%";
    span.title = text;
    bar.appendChild(span);
  };
  if (starting !== null) {
    part("world-starting", starting - world.startedAt,
         "starting " + seconds(starting - world.startedAt));
  } else {
    part("world-starting", total, "starting");
  }
  if (ready !== null) {
    part("world-up", (stopped !== null ? stopped : world.startedAt + total) - ready, "up");
  }
  lane.appendChild(bar);
  const times = element("p", "world-times");
  if (ready !== null) times.appendChild(element("span", "", "ready after " +
      seconds(ready - world.startedAt) + " · "));
  if (stopped !== null) {
    times.appendChild(element("span", "", (ready !== null ? "stopped, up " : "gave up after ") +
        seconds(stopped - world.startedAt)));
  } else {
    times.appendChild(elapsedNode("span", "", world.startedAt,
        ready !== null ? "up" : "starting"));
  }
  lane.appendChild(times);
  if (world.reason) lane.appendChild(element("pre", "world-reason", world.reason));
  return lane;
}

function drawWorlds() {
  const box = document.getElementById("worlds");
  box.hidden = !worlds.some((w) => w);
  box.replaceChildren(...worlds.filter((w) => w).map(worldLane));
  worldsDirty = false;
}

// What changed since the last drawing: only that is drawn again, so a long run stays cheap.
const dirty = { all: true, suites: new Set(), tests: [] };
const sections = [];

function placeSection(main, index) {
  const node = suiteSection(suites[index]);
  if (sections[index]) {
    sections[index].replaceWith(node);
  } else {
    main.appendChild(node);
  }
  sections[index] = node;
}

function placeRow(suiteIndex, index) {
  const section = sections[suiteIndex];
  const test = suites[suiteIndex] && suites[suiteIndex].tests[index];
  if (!section || !test) return;
  const table = section.querySelector("table");
  const row = testRow(test);
  if (table.rows[index]) {
    table.rows[index].replaceWith(row);
  } else {
    table.appendChild(row);
  }
  // A running suite's title says its fixture's phase, which its tests' states tell.
  if (suites[suiteIndex].state === "running") {
    section.querySelector("h2").replaceWith(suiteTitle(suites[suiteIndex]));
  }
}

function draw() {
  drawPending = false;
  drawSummary();
  if (worldsDirty) drawWorlds();
  const main = document.getElementById("suites");
  if (dirty.all) {
    sections.length = 0;
    main.replaceChildren();
    suites.forEach((suite, index) => { if (suite) placeSection(main, index); });
  } else {
    for (const index of [...dirty.suites].sort((a, b) => a - b)) placeSection(main, index);
    for (const [suiteIndex, index] of dirty.tests) {
      if (!dirty.suites.has(suiteIndex)) placeRow(suiteIndex, index);
    }
  }
  dirty.all = false;
  dirty.suites.clear();
  dirty.tests.length = 0;
}

function scheduleDraw() {
  if (!drawPending) {
    drawPending = true;
    window.requestAnimationFrame(draw);
  }
}

function apply(change) {
  if (change.type === "run") {
    Object.assign(run, change.run);
  } else if (change.type === "suite") {
    suites[change.index] = change.suite;
    dirty.suites.add(change.index);
  } else if (change.type === "world") {
    worlds[change.index] = change.world;
    worldsDirty = true;
  } else if (change.type === "test") {
    const suite = suites[change.suite];
    if (suite) {
      suite.tests[change.index] = change.test;
      dirty.tests.push([change.suite, change.index]);
    }
  }
  if (typeof change.seq === "number") lastSeq = Math.max(lastSeq, change.seq);
}

function setConnection(text) {
  document.getElementById("connection").textContent = text;
}

function listen() {
  source = new EventSource("/events?since=" + lastSeq);
  source.onopen = () => setConnection("live");
  source.onmessage = (event) => {
    const change = JSON.parse(event.data);
    setClock(change.now);
    apply(change);
    scheduleDraw();
    if (run.state === "finished") {
      source.close();  // the final result stays on the page
      setConnection("the run has ended");
    }
  };
  source.onerror = () => {
    if (run.state === "finished") {
      source.close();
      setConnection("the run has ended");
    } else {
      setConnection("connection lost; retrying…");
    }
  };
}

async function start() {
  try {
    const response = await fetch("/snapshot", { cache: "no-store" });
    const snapshot = await response.json();
    Object.assign(run, snapshot.run);
    suites.length = 0;
    suites.push(...snapshot.suites);
    worlds.length = 0;
    worlds.push(...(snapshot.worlds || []));
    worldsDirty = true;
    lastSeq = snapshot.seq;
    setClock(snapshot.now);
    dirty.all = true;
  } catch (error) {
    setConnection("cannot read the run: " + error);
  }
  draw();
  if (run.state === "finished") {
    setConnection("the run has ended");
  } else {
    listen();
  }
}

start();
