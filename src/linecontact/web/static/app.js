// linecontact calculator: the form, the API call, the results, the plot. No dependencies.
"use strict";
(function () {
  const spec = JSON.parse(document.getElementById("spec").textContent);
  const form = document.getElementById("form");
  const $ = (id) => document.getElementById(id);
  let last = null; // the last JSON result
  let job = null;

  function factor(name) {
    const u = $("u-" + name);
    return u ? parseFloat(u.value) : 1.0;
  }
  function show(v) { return Number.isFinite(v) ? String(+v.toPrecision(12)) : String(v); }

  // the page's state: its query string, in SI units, named as the CLI flags
  function fill() {
    const q = new URLSearchParams(location.search);
    for (const f of spec.fields) {
      const el = $("f-" + f.name);
      if (!el) continue;
      const given = q.has(f.name) ? q.getAll(f.name).join(",") : f.default;
      if (f.kind === "material") { if (given) el.value = given; continue; }
      el.value = given === "" ? "" : given.split(",").map((x) => show(parseFloat(x) / factor(f.name))).join(",");
    }
  }
  for (const f of spec.fields) {
    const u = $("u-" + f.name);
    if (!u) continue;
    let before = factor(f.name);
    u.addEventListener("change", () => {
      const el = $("f-" + f.name);
      const now = factor(f.name);
      if (el.value.trim() !== "") {
        el.value = el.value.split(",").map((x) => show(parseFloat(x) * before / now)).join(",");
      }
      before = now;
    });
  }

  function params(aux) {
    const p = new URLSearchParams();
    for (const f of spec.fields) {
      if (Boolean(f.aux) !== Boolean(aux)) continue; // a field of the marked point, or of the page's command
      const el = $("f-" + f.name);
      const raw = el.value.trim();
      if (raw === "") continue;
      if (f.kind === "material") { p.append(f.name, raw); continue; }
      const vals = raw.split(",").map((x) => x.trim()).filter((x) => x !== "");
      const si = vals.map((x) => {
        const v = Number(x);
        return Number.isFinite(v) ? String(Number((v * factor(f.name)).toPrecision(15))) : x; // the server names a bad one
      });
      p.append(f.name, si.join(","));
    }
    if (!aux) for (const [k, v] of Object.entries(spec.fixed || {})) p.append(k, v);
    return p;
  }

  function clearMessages() {
    for (const m of document.querySelectorAll(".message")) m.textContent = "";
    for (const el of document.querySelectorAll(".invalid")) el.classList.remove("invalid");
    $("form-error").textContent = "";
  }

  function error(doc) {
    const e = (doc && doc.error) || { message: "the server gave no answer" };
    const box = e.parameter && $("m-" + e.parameter);
    if (box) {
      const u = $("u-" + e.parameter);
      const typed = $("f-" + e.parameter).value;
      const unit = u ? " " + u.selectedOptions[0].textContent : "";
      box.textContent = e.message + (u ? ` (in SI units; you gave ${typed}${unit})` : "");
      $("f-" + e.parameter).classList.add("invalid");
    } else {
      $("form-error").textContent = e.message;
    }
  }

  function cell(key, v) {
    const td = document.createElement("td");
    td.dataset.key = key;
    td.dataset.value = v === null ? "null" : typeof v === "object" ? JSON.stringify(v) : String(v);
    td.textContent = v === null ? "—" : typeof v === "number" ? show(v) : typeof v === "object" ? JSON.stringify(v) : String(v);
    return td;
  }

  function results(doc) {
    const box = $("results");
    box.textContent = "";
    const recs = doc.results || [];
    const keys = [];
    for (const r of recs) for (const k of Object.keys(r)) if (!keys.includes(k)) keys.push(k);
    const wrap = document.createElement("div");
    wrap.className = "scroll";
    const t = document.createElement("table");
    const head = t.createTHead().insertRow();
    for (const k of keys) {
      const th = document.createElement("th");
      const unit = doc.units && doc.units[k];
      th.textContent = k + (unit && unit !== "1" ? " [" + unit + "]" : "");
      head.appendChild(th);
    }
    const body = t.createTBody();
    recs.forEach((r, i) => {
      const row = body.insertRow();
      row.dataset.index = String(i);
      for (const k of keys) row.appendChild(cell(k, k in r ? r[k] : null));
    });
    wrap.appendChild(t);
    const h = document.createElement("h2");
    h.textContent = "Results";
    box.append(h, wrap);
    const params = document.createElement("dl");
    params.className = "parameters";
    for (const [k, v] of Object.entries(doc.parameters || {})) {
      const dt = document.createElement("dt");
      dt.textContent = k;
      const dd = document.createElement("dd");
      dd.dataset.key = k;
      dd.dataset.value = typeof v === "object" ? JSON.stringify(v) : String(v);
      dd.textContent = typeof v === "number" ? show(v) : String(v);
      params.append(dt, dd);
    }
    const h2 = document.createElement("h2");
    h2.textContent = "Parameters";
    box.append(h2, params);
  }

  const NS = "http://www.w3.org/2000/svg";
  function plot(doc, mark, P = spec.plot, figId = "plot", svgId = "plot-svg") {
    const fig = $(figId);
    fig.textContent = "";
    if (!P) return;
    const pts = (doc.results || []).map((r) => [r[P.x], r[P.y], P.color ? r[P.color] : null])
      .filter((p) => Number.isFinite(p[0]) && Number.isFinite(p[1]));
    if (!pts.length) return;
    const W = 640, H = 360, L = 70, B = 45, T = 15, R = 15;
    let [x0, x1] = [Math.min(...pts.map((p) => p[0])), Math.max(...pts.map((p) => p[0]))];
    let [y0, y1] = [Math.min(...pts.map((p) => p[1])), Math.max(...pts.map((p) => p[1]))];
    if (x0 === x1) { x0 -= 1; x1 += 1; }
    if (y0 === y1) { y0 -= 1; y1 += 1; }
    const view = { x0, x1, y0, y1 };
    const svg = document.createElementNS(NS, "svg");
    svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
    svg.setAttribute("role", "img");
    svg.setAttribute("id", svgId);
    function draw() {
      svg.textContent = "";
      const sx = (x) => L + (x - view.x0) / (view.x1 - view.x0) * (W - L - R);
      const sy = (y) => H - B - (y - view.y0) / (view.y1 - view.y0) * (H - B - T);
      const add = (tag, attrs, text) => {
        const e = document.createElementNS(NS, tag);
        for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
        if (text !== undefined) e.textContent = text;
        svg.appendChild(e);
        return e;
      };
      add("rect", { x: 0, y: 0, width: W, height: H, fill: "white" });
      add("line", { x1: L, y1: H - B, x2: W - R, y2: H - B, stroke: "black" });
      add("line", { x1: L, y1: T, x2: L, y2: H - B, stroke: "black" });
      for (let i = 0; i <= 4; i++) {
        const xv = view.x0 + (view.x1 - view.x0) * i / 4, yv = view.y0 + (view.y1 - view.y0) * i / 4;
        add("text", { x: sx(xv), y: H - B + 16, "text-anchor": "middle", "font-size": 11 }, show(+xv.toPrecision(3)));
        add("text", { x: L - 6, y: sy(yv) + 4, "text-anchor": "end", "font-size": 11 }, show(+yv.toPrecision(3)));
      }
      add("text", { x: (L + W - R) / 2, y: H - 8, "text-anchor": "middle", "font-size": 12 }, P.xlabel);
      add("text", { x: 14, y: (T + H - B) / 2, "text-anchor": "middle", "font-size": 12,
        transform: `rotate(-90 14 ${(T + H - B) / 2})` }, P.ylabel);
      const inside = pts.filter((p) => p[0] >= view.x0 && p[0] <= view.x1 && p[1] >= view.y0 && p[1] <= view.y1);
      if (!P.points) {
        add("polyline", { points: inside.map((p) => `${sx(p[0])},${sy(p[1])}`).join(" "), fill: "none", stroke: "#1f77b4", "stroke-width": 2 });
      }
      if (mark && mark.y !== undefined && mark.y >= view.y0 && mark.y <= view.y1) {
        add("line", { x1: L, y1: sy(mark.y), x2: W - R, y2: sy(mark.y), stroke: "#d62728",
          "stroke-width": 2, "stroke-dasharray": "6 4", id: figId + "-mark" });
        add("text", { x: L + 4, y: sy(mark.y) - 4, "font-size": 12, fill: "#d62728" }, mark.label);
      }
      if (mark && mark.x !== undefined && mark.x >= view.x0 && mark.x <= view.x1) {
        add("line", { x1: sx(mark.x), y1: T, x2: sx(mark.x), y2: H - B, stroke: "#d62728",
          "stroke-width": 2, "stroke-dasharray": "6 4", id: "mark" });
        add("text", { x: sx(mark.x) + 4, y: T + 12, "font-size": 12, fill: "#d62728" }, mark.label);
      }
      for (const p of inside) {
        const c = add("circle", { cx: sx(p[0]), cy: sy(p[1]), r: P.points ? 4 : 3,
          fill: p[2] === false ? (P.falseColor || "#bbbbbb") : "#1f77b4", "data-x": p[0], "data-y": p[1] });
        const t = document.createElementNS(NS, "title");
        t.textContent = `${P.xlabel} = ${show(p[0])}\n${P.ylabel} = ${show(p[1])}`;
        c.appendChild(t);
      }
    }
    // zoom: the wheel zooms about the pointer; double-click resets
    svg.addEventListener("wheel", (ev) => {
      ev.preventDefault();
      const k = ev.deltaY > 0 ? 1.25 : 0.8;
      const r = svg.getBoundingClientRect();
      const fx = Math.min(Math.max((ev.clientX - r.left) / r.width * W - L, 0) / (W - L - R), 1);
      const fy = 1 - Math.min(Math.max((ev.clientY - r.top) / r.height * H - T, 0) / (H - B - T), 1);
      const cx = view.x0 + fx * (view.x1 - view.x0), cy = view.y0 + fy * (view.y1 - view.y0);
      view.x0 = cx - (cx - view.x0) * k; view.x1 = cx + (view.x1 - cx) * k;
      view.y0 = cy - (cy - view.y0) * k; view.y1 = cy + (view.y1 - cy) * k;
      draw();
    }, { passive: false });
    svg.addEventListener("dblclick", () => { Object.assign(view, { x0, x1, y0, y1 }); draw(); });
    draw();
    fig.appendChild(svg);
    const cap = document.createElement("figcaption");
    cap.textContent = "hover a point for its values; the wheel zooms, a double-click resets";
    if (P.legend) cap.textContent = P.legend + "; " + cap.textContent;
    if (mark && mark.x !== undefined && !(mark.x >= x0 && mark.x <= x1)) {
      cap.textContent += `; ${mark.label}: ${P.xlabel} ${show(mark.x)}, outside this map`;
    }
    fig.appendChild(cap);
  }

  function download(name, type, data) {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([data], { type }));
    a.download = name;
    a.click();
  }

  function csv(doc) {
    const lines = [];
    for (const k of ["linecontact", "command", "parameters", "units"]) lines.push(`# ${k}: ${JSON.stringify(doc[k])}`);
    const recs = doc.results || [];
    const keys = [];
    for (const r of recs) for (const k of Object.keys(r)) if (!keys.includes(k)) keys.push(k);
    lines.push(keys.join(","));
    for (const r of recs) {
      lines.push(keys.map((k) => {
        const v = r[k];
        if (v === null || v === undefined) return "";
        const s = typeof v === "object" ? JSON.stringify(v) : String(v);
        return /[",\n]/.test(s) ? '"' + s.replace(/"/g, '""') + '"' : s;
      }).join(","));
    }
    return lines.join("\n") + "\n";
  }

  function downloads(doc) {
    const box = $("downloads");
    box.textContent = "";
    const add = (label, fn) => {
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = label;
      b.id = "download-" + label.toLowerCase();
      b.addEventListener("click", fn);
      box.appendChild(b);
    };
    add("JSON", () => download(spec.command + ".json", "application/json", JSON.stringify(doc) + "\n"));
    add("CSV", () => download(spec.command + ".csv", "text/csv", csv(doc)));
    const svg = $("plot-svg");
    if (svg) {
      const text = () => new XMLSerializer().serializeToString(svg);
      add("SVG", () => download(spec.command + ".svg", "image/svg+xml", text()));
      add("PNG", () => {
        const img = new Image();
        img.onload = () => {
          const c = document.createElement("canvas");
          c.width = 1280; c.height = 720;
          c.getContext("2d").drawImage(img, 0, 0, c.width, c.height);
          c.toBlob((b) => download(spec.command + ".png", "image/png", b));
        };
        img.src = "data:image/svg+xml;charset=utf-8," + encodeURIComponent(text());
      });
    }
  }

  function equivalent(p) {
    const words = ["linecontact", spec.command];
    const values = {};
    for (const [k, v] of p.entries()) {
      const flag = "--" + k.replace(/_/g, "-");
      if (v === "true") words.push(flag); else words.push(flag, ...v.split(","));
      values[k] = v;
    }
    if (spec.upload) words.push("--data", "measurements.csv");
    $("cli").textContent = words.join(" ");
    let py = spec.python || "";
    py = py.replace(/\{(\w+)(!r)?\}/g, (_, k, r) => {
      const v = values[k] === undefined ? "None" : values[k];
      return r ? JSON.stringify(v) : v;
    });
    $("py").textContent = "import linecontact as lc\n" + py;
  }

  // the regime of the Maugis parameter (Johnson and Greenwood's map for line contact)
  function regime(doc) {
    const r = (doc.results || [])[0] || {};
    const lam = "maugis_parameter" in r ? r.maugis_parameter : (doc.parameters || {}).maugis_parameter;
    if (!Number.isFinite(lam)) return;
    const name = lam < 0.1 ? "rigid (DMT-like): adhesion outside the contact"
      : lam > 5 ? "JKR: a compliant contact, adhesion at its edge"
      : "Maugis-Dugdale transition between DMT and JKR";
    const p = document.createElement("p");
    p.id = "regime";
    p.dataset.key = "maugis_parameter";
    p.dataset.value = String(lam);
    p.textContent = `Maugis parameter ${show(lam)}: ${name}`;
    $("results").prepend(p);
  }

  async function marked() {
    if (!spec.mark) return null;
    const r = await fetch("/api/v1/" + spec.mark.command + "?" + params(true).toString());
    const doc = await r.json().catch(() => null);
    if (r.status !== 200) { error(doc); return null; }
    const v = doc.results[0][spec.mark.key];
    const p = document.createElement("p");
    p.id = "mark-value";
    p.dataset.key = spec.mark.key;
    p.dataset.value = String(v);
    p.textContent = `${spec.mark.label}: ${spec.mark.key} = ${show(v)}`;
    $("status").after(p);
    return { x: v, label: spec.mark.label };
  }

  // the motion map of the pushed wire: first motion over push height and friction stress
  async function motion(p) {
    const fig = $("motion");
    if (!spec.motion || !fig) return;
    const R = parseFloat(p.get("radius")), tau = parseFloat(p.get("tau0"));
    if (!(R > 0 && tau > 0)) return;
    const hs = Array.from({ length: 21 }, (_, i) => String(Number((2 * R * i / 20).toPrecision(12))));
    const pts = [];
    for (const f of [0.01, 0.03, 0.1, 0.3, 1, 3, 10, 30, 100]) {
      const q = new URLSearchParams(p);
      q.set("tau0", String(Number((tau * f).toPrecision(12))));
      q.set("height", hs.join(","));
      const r = await fetch("/api/v1/push?" + q.toString());
      if (r.status !== 200) continue;
      const doc = await r.json();
      for (const rec of doc.results) {
        pts.push({ H_m: rec.H_m, log10_tau0: Math.log10(tau * f), rolls: rec.first_motion === "roll" });
      }
    }
    const P = { x: "H_m", y: "log10_tau0", xlabel: "push height H [m]",
      ylabel: "log10 tau0 [Pa]", points: true, color: "rolls", falseColor: "#ff7f0e",
      legend: "blue: rolls first, orange: slides first" };
    plot({ results: pts }, { y: Math.log10(tau), label: "your wire" }, P, "motion", "motion-svg");
  }

  // the few values a page is for, above its table (each with its key and full value)
  function headline(doc) {
    if (!spec.headline) return;
    const r = (doc.results || [])[0] || {};
    const dl = document.createElement("dl");
    dl.className = "headline";
    dl.id = "headline";
    for (const [k, label] of Object.entries(spec.headline)) {
      if (!(k in r)) continue;
      const dt = document.createElement("dt");
      const unit = doc.units && doc.units[k];
      dt.textContent = label + (unit && unit !== "1" ? ` [${unit}]` : "");
      const dd = document.createElement("dd");
      dd.dataset.key = k;
      dd.dataset.value = r[k] === null ? "null" : String(r[k]);
      dd.textContent = r[k] === null ? "—" : typeof r[k] === "number" ? show(r[k]) : String(r[k]);
      dl.append(dt, dd);
    }
    $("results").prepend(dl);
  }

  async function done(doc) {
    last = doc;
    results(doc);
    headline(doc);
    regime(doc);
    const old = $("mark-value");
    if (old) old.remove();
    plot(doc, await marked());
    motion(params());
    downloads(doc);
    $("status").textContent = `done: ${(doc.results || []).length} record(s)`;
  }

  async function poll(id) {
    const r = await fetch("/api/v1/jobs/id/" + id);
    const doc = await r.json();
    if (doc.state === "queued" || doc.state === "running") {
      const pr = doc.progress ? `${doc.progress.done}/${doc.progress.total} curves, ` : "";
      const what = doc.state === "queued" ? "waiting for a worker..." : "computing...";
      $("status").textContent = `${what} ${pr}${doc.elapsed_s.toFixed(1)} s`;
      job = setTimeout(() => poll(id), 500);
      return;
    }
    $("cancel").hidden = true;
    job = null;
    if (doc.state === "done") done(doc.result);
    else if (doc.state === "cancelled") $("status").textContent = "cancelled";
    else { $("status").textContent = ""; error(doc); }
  }

  form.addEventListener("submit", async (ev) => {
    ev.preventDefault();
    clearMessages();
    const p = params();
    const all = new URLSearchParams([...p.entries(), ...params(true).entries()]);
    history.replaceState(null, "", location.pathname + "?" + all.toString());
    equivalent(p);
    $("status").textContent = "computing...";
    let r;
    try {
      if (spec.job) {
        r = await fetch("/api/v1/jobs/" + spec.command + "?" + p.toString(), { method: "POST" });
        const doc = await r.json();
        if (r.status !== 202) { $("status").textContent = ""; error(doc); return; }
        $("cancel").hidden = false;
        $("cancel").onclick = async () => {
          await fetch("/api/v1/jobs/id/" + doc.id, { method: "DELETE" });
        };
        poll(doc.id);
        return;
      }
      if (spec.upload) {
        const fd = new FormData();
        for (const [k, v] of p.entries()) fd.append(k, v);
        const file = $("f-data").files[0];
        if (file) fd.append("data", file);
        r = await fetch("/api/v1/" + spec.command, { method: "POST", body: fd });
      } else {
        r = await fetch("/api/v1/" + spec.command + "?" + p.toString());
      }
    } catch (e) {
      $("status").textContent = "";
      $("form-error").textContent = "the server cannot be reached";
      return;
    }
    const doc = await r.json().catch(() => null);
    if (r.status === 200) done(doc);
    else { $("status").textContent = ""; error(doc); }
  });

  fill();
  if (location.search) form.requestSubmit();
})();
