// What the HTML report and the live page both draw (the live page serves this file too): a
// test's strip of recent runs (--history) and the plot of one measurement's values, across
// repetitions or across runs. SVG made with createElementNS, text set with textContent only:
// nothing from the data becomes markup. Coloured by the page's variables (trends.css).
"use strict";
window.rtfTrends = (function () {
  const svgNs = "http://www.w3.org/2000/svg";
  const svg = (tag, attrs) => {
    const node = document.createElementNS(svgNs, tag);
    for (const key in attrs) node.setAttribute(key, attrs[key]);
    return node;
  };
  const titled = (node, text) => {
    const title = svg("title", {});
    title.textContent = text;
    node.appendChild(title);
    return node;
  };
  const span = (cls, text) => {
    const node = document.createElement("span");
    node.className = cls;
    if (text !== undefined) node.textContent = text;
    return node;
  };
  const kind = (s) => s === "passed" ? "passed" : s === "skipped" ? "skipped" :
      s === "interrupted" || s === "flaky" ? "other" : "failing";

  // A test's last runs: a cell per run coloured by its state, a sparkline of their times and
  // its flaky rate. `history`: {states, durations, flakyRate}.
  const historyStrip = (history) => {
    const box = span("history");
    box.title = "last " + history.states.length + " runs";
    const cells = span("cells");
    history.states.forEach((s, i) => {
      const cell = span("cell " + kind(s));
      cell.title = s + " (" + history.durations[i].toFixed(3) + " s)";
      cells.appendChild(cell);
    });
    box.appendChild(cells);
    const d = history.durations;
    if (d.length > 1) {
      const line = svg("svg", { viewBox: "0 0 60 14", class: "sparkline" });
      const top = Math.max(...d) || 1;
      line.appendChild(svg("polyline", { points: d.map((v, i) =>
          (60 * i / (d.length - 1)).toFixed(1) + "," + (13 - 12 * v / top).toFixed(1)).join(" ") }));
      box.appendChild(line);
    }
    box.appendChild(span("note flaky-rate", "flaky " + Math.round(100 * history.flakyRate) + "%"));
    return box;
  };

  // One measurement's values as a small plot: a line through them in order, its limits as
  // dashed lines, a point per value (red when outside its limits, ringed when `current`).
  // `series`: {name, unit, low, high, points: [{value, label, outside, current}]}; `what`
  // names the plot ("repetitions", "history"). The values are in the SVG's data attributes,
  // for whoever reads the page by script.
  const measurementPlot = (series, what) => {
    const width = 160, height = 40, pad = 4;
    const points = series.points;
    const values = points.map((p) => p.value);
    const limits = [series.low, series.high].filter((v) => typeof v === "number");
    let low = Math.min(...values, ...limits);
    let high = Math.max(...values, ...limits);
    if (high - low < 1e-12) { low -= 1; high += 1; }
    const margin = (high - low) * 0.08;
    low -= margin; high += margin;
    const x = (i) => points.length === 1 ? width / 2 :
        pad + (width - 2 * pad) * i / (points.length - 1);
    const y = (v) => height - pad - (height - 2 * pad) * (v - low) / (high - low);
    const unit = series.unit ? " " + series.unit : "";
    const plot = svg("svg", { viewBox: "0 0 " + width + " " + height, class: "measure-plot " + what,
                              role: "img", "aria-label": series.name + " across " + what });
    plot.dataset.name = series.name;
    plot.dataset.what = what;
    plot.dataset.values = JSON.stringify(values);
    for (const [side, v] of [["low", series.low], ["high", series.high]]) {
      if (typeof v !== "number") continue;
      const line = svg("line", { class: "limit " + side, x1: 0, x2: width, y1: y(v), y2: y(v) });
      line.dataset.value = v;
      plot.appendChild(titled(line, side + " limit " + v + unit));
    }
    if (points.length > 1) {
      plot.appendChild(svg("polyline", { class: "trend",
          points: points.map((p, i) => x(i).toFixed(1) + "," + y(p.value).toFixed(1)).join(" ") }));
    }
    points.forEach((p, i) => {
      const dot = svg("circle", { class: "point" + (p.outside ? " outside" : "") +
                                         (p.current ? " current" : ""),
                                  cx: x(i).toFixed(1), cy: y(p.value).toFixed(1),
                                  r: p.current ? 3.2 : 2.4 });
      dot.dataset.value = p.value;
      plot.appendChild(titled(dot, series.name + " = " + p.value + unit +
          (p.label ? " (" + p.label + ")" : "") + (p.outside ? ", outside its limits" : "")));
    });
    return plot;
  };

  // Outside limits [low, high] (either may be missing)?
  const outside = (v, low, high) =>
      (typeof low === "number" && v < low) || (typeof high === "number" && v > high);

  // The history's series of the measurement `name` ({name, unit, values, ago, outside, low,
  // high}, the runner's --history), as measurementPlot takes it; null when it has none.
  const historySeries = (history, name) => {
    const found = ((history && history.measurements) || []).find((m) => m.name === name);
    if (!found) return null;
    const bad = new Set(found.outside || []);
    return { name: found.name, unit: found.unit, low: found.low, high: found.high,
             points: found.values.map((value, i) => ({
               value: value, outside: bad.has(i), current: found.ago[i] === 0,
               label: found.ago[i] === 0 ? "this run" : found.ago[i] === 1 ? "1 run ago"
                   : found.ago[i] + " runs ago" })) };
  };

  return { historyStrip, measurementPlot, historySeries, outside };
})();
