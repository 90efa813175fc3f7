// linecontact calculator: the form, the API call, the answer, the plot. No dependencies.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const spec = JSON.parse($("spec").textContent);
  const UNITS = spec.units; // kind -> [[unit, factor to SI], ...], the first the default
  const SI_UNIT = { length: "m", modulus: "Pa", stress: "Pa", work: "J/m^2", force: "N/m", energy: "J/m" };
  const form = $("form");
  const fields = Object.fromEntries(spec.fields.map((f) => [f.name, f]));
  let job = null;

  // ---------------------------------------------------------------------------------------
  // units and numbers

  // the unit chosen for a field: [label, factor to SI]
  function unitOf(name) {
    const f = fields[name];
    const kind = f ? f.kind : "none";
    const u = $("u-" + name);
    const list = UNITS[kind] || [["", 1]];
    return (u && list.find((x) => x[0] === u.value)) || list[0];
  }
  // the unit of a kind on this page: that of the first shown field of the kind, or its default
  function unitOfKind(kind, prefer) {
    for (const name of [...(prefer || []), ...spec.fields.map((f) => f.name)]) {
      const f = fields[name];
      if (f && f.kind === kind && active(f) && $("u-" + name)) return unitOf(name);
    }
    return (UNITS[kind] || [["", 1]])[0];
  }
  // 4 significant digits (5 in the table), exponents only far from 1
  function fmt(v, digits = 4) {
    if (typeof v !== "number") return v === null || v === undefined ? "—" : String(v);
    if (!Number.isFinite(v)) return v > 0 ? "∞" : v < 0 ? "−∞" : "—";
    const a = Math.abs(v);
    if (a !== 0 && (a < 1e-3 || a >= 1e6)) return v.toExponential(digits - 1).replace(/\.?0+e/, "e");
    return String(Number(v.toPrecision(digits)));
  }
  // an SI value in the unit chosen for its kind: "3.922 nm"
  function qty(si, kind, prefer) {
    const [u, f] = unitOfKind(kind, prefer);
    return fmt(si / f) + (u ? " " + u : "");
  }
  // a force on the whole wire [N], with the prefix that reads best
  function newtons(si) {
    const a = Math.abs(si);
    for (const [u, f] of [["N", 1], ["mN", 1e-3], ["µN", 1e-6], ["nN", 1e-9], ["pN", 1e-12]]) {
      if (a >= f) return fmt(si / f) + " " + u;
    }
    return fmt(si / 1e-15) + " fN";
  }
  // a value with its record key and full precision
  function val(key, si, text) {
    const s = document.createElement("span");
    s.className = "value";
    s.dataset.key = key;
    s.dataset.value = si === null || si === undefined ? "null" : String(si);
    s.textContent = text;
    return s;
  }
  // an SI value as the command line and Python take it: 15 digits, the shortest text
  function siText(x) {
    const v = Number(x.toPrecision(15));
    const a = Math.abs(v);
    return a !== 0 && (a < 1e-3 || a >= 1e6) ? v.toExponential().replace("e+", "e") : String(v);
  }
  function show(v) { return Number.isFinite(v) ? String(+v.toPrecision(12)) : String(v); }

  // ---------------------------------------------------------------------------------------
  // the form: alternatives, parsing, the page's state in its link

  // a field's alternative: its group and the options it belongs to ("tau0:presets|moduli")
  const altGroup = (f) => (f.alt ? f.alt.split(":")[0] : null);
  const altOptions = (f) => (f.alt ? f.alt.split(":")[1].split("|") : []);
  function active(f) {
    if (!f.alt) return true;
    const sel = $("a-" + altGroup(f));
    return !sel || altOptions(f).includes(sel.value);
  }
  function showAlternatives() {
    for (const f of spec.fields) {
      const w = $("w-" + f.name);
      if (w) w.hidden = !active(f);
    }
  }
  for (const g of Object.keys(spec.alts || {})) $("a-" + g).addEventListener("change", showAlternatives);

  const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
  const chosen = (f) => f.kind === "material" || f.kind === "choice"; // a list, not a number
  const WITH_UNIT = /^([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*([^\d\s.,+-].*)$/;
  const norm = (u) => u.toLowerCase().replace(/[µμ]/g, "u").replace(/²/g, "^2").replace(/\s+/g, "");

  // a field's values in SI units, or the message that says what is wrong, in its words
  function parse(f) {
    const el = $("f-" + f.name);
    const raw = el.value.trim();
    if (f.kind === "material") return { values: [raw] };
    if (f.kind === "choice") return { values: raw === f.default ? [] : [raw] }; // the default: not sent
    if (raw === "") return { values: [] };
    const [unit, factor] = unitOf(f.name);
    const inUnit = unit ? ` (in ${unit}, the unit chosen beside it)` : "";
    if (!f.many && /^[+-]?\d*,\d+$/.test(raw)) {
      return { error: `“${raw}” has a decimal comma: write ${raw.replace(",", ".")}, with a point${inUnit}` };
    }
    let tokens = f.many ? raw.split(/\s*[,;]\s*/) : [raw];
    tokens = tokens.flatMap((t) => (t.split(/\s+/).every((x) => NUMBER.test(x)) ? t.split(/\s+/) : [t]));
    tokens = tokens.filter((t) => t !== "");
    const values = [];
    for (const t of tokens) {
      if (NUMBER.test(t)) {
        const v = Number(t);
        if (!Number.isFinite(v * factor)) return { error: `${t} ${unit} is too large a number for the ${f.label}` };
        values.push(siText(v * factor));
        continue;
      }
      const m = WITH_UNIT.exec(t);
      if (m) {
        const known = (UNITS[f.kind] || []).find((u) => u[0] && norm(u[0]) === norm(m[2]));
        if (known) {
          return { error: `type the number alone (${m[1]}) and choose ${known[0]} in the list beside it: “${t}” is not a number` };
        }
        const units = (UNITS[f.kind] || []).map((u) => u[0]).filter(Boolean);
        return { error: `“${t}” is not a number: the ${f.label} is a number` + (units.length ? `, its unit (${units.join(", ")}) chosen beside it` : "") };
      }
      return { error: `“${t}” is not a number${inUnit}` };
    }
    if (!f.many && values.length > 1) return { error: `the ${f.label} takes one value, got ${values.length} (“${raw}”)` };
    return { values };
  }

  // the inputs in SI units by name (the active fields of the page's command, or the marked point's)
  function inputs(aux) {
    const out = {};
    const errors = {};
    for (const f of spec.fields) {
      if (!active(f) || Boolean(f.aux) !== Boolean(aux)) continue;
      const got = parse(f);
      if (got.error) errors[f.name] = got.error;
      else if (got.values.length) out[f.name] = got.values;
    }
    return { values: out, errors };
  }
  function params(values, aux) {
    const p = new URLSearchParams();
    for (const [k, v] of Object.entries(values)) p.append(k, v.join(","));
    if (!aux) for (const [k, v] of Object.entries(spec.fixed || {})) p.append(k, v);
    return p;
  }

  // the link's query: the inputs in SI units, named as the CLI flags; units as u.NAME
  function fill() {
    const q = new URLSearchParams(location.search);
    const linked = [...q.keys()].some((k) => k in fields);
    for (const [g, a] of Object.entries(spec.alts || {})) { // the alternative the link gives
      let given = null;
      for (const [opt] of a.options) {
        if (spec.fields.some((f) => f.alt === `${g}:${opt}` && !chosen(f) && q.has(f.name))) given = opt;
      }
      if (given === null) { // else the option most of the link's keys belong to (a list's too)
        let most = 0;
        for (const [opt] of a.options) {
          const n = spec.fields.filter((f) => altGroup(f) === g && altOptions(f).includes(opt) && q.has(f.name)).length;
          if (n > most) { most = n; given = opt; }
        }
      }
      if (given !== null) $("a-" + g).value = given;
    }
    for (const f of spec.fields) {
      const el = $("f-" + f.name);
      if (!el) continue;
      const u = $("u-" + f.name);
      if (u && q.has("u." + f.name) && (UNITS[f.kind] || []).some((x) => x[0] === q.get("u." + f.name))) u.value = q.get("u." + f.name);
      const given = q.has(f.name) ? q.getAll(f.name).join(",") : linked && !chosen(f) ? "" : f.default;
      if (chosen(f)) { if (given) el.value = given; continue; }
      const factor = unitOf(f.name)[1];
      el.value = given === "" ? "" : given.split(",").map((x) => (NUMBER.test(x.trim()) ? show(parseFloat(x) / factor) : x)).join(f.many ? ", " : ",");
    }
    showAlternatives();
    // every key of the link is taken, or named: never ignored. The keys the page writes: its
    // fields', their units' (u.NAME) and its fixed ones; a key of an alternative not chosen
    // (a modulus and the presets) is named too (the API refuses most such pairs with a 422)
    const known = new Set(Object.keys(spec.fixed || {}));
    for (const f of spec.fields) { known.add(f.name); known.add("u." + f.name); }
    const keys = [...new Set(q.keys())];
    const quote = (ks) => ks.map((k) => `“${k}”`).join(", ");
    const said = [];
    const unknown = keys.filter((k) => !known.has(k));
    if (unknown.length) {
      said.push(`this link sets ${quote(unknown)}, which the page “${spec.title}” does not take `
        + `(the API answers 422 for ${unknown.length > 1 ? "them" : "it"})`);
    }
    for (const [g, a] of Object.entries(spec.alts || {})) {
      const given = keys.filter((k) => fields[k] && altGroup(fields[k]) === g);
      const off = given.filter((k) => !active(fields[k]));
      if (!off.length) continue;
      const chosen = given.filter((k) => active(fields[k]));
      const words = a.options.filter(([opt]) => given.some((k) => altOptions(fields[k]).includes(opt))).map((o) => o[1]);
      said.push(`this link sets ${quote(chosen)} and ${quote(off)}, alternatives of “${a.label}” `
        + `(${words.join("; ")}): the page takes one of them`);
    }
    if (said.length) $("form-error").textContent = said.join("; ") + ": nothing is computed; change the form and press Compute";
    return said.length === 0;
  }

  // ---------------------------------------------------------------------------------------
  // messages: beside the field, in its words and unit

  function clearMessages() {
    for (const m of document.querySelectorAll(".message")) { m.textContent = ""; m.className = "message"; }
    for (const el of document.querySelectorAll(".invalid")) el.classList.remove("invalid");
    $("form-error").textContent = "";
  }
  const flagName = (flag) => flag.replace(/^--/, "").replace(/-/g, "_");

  // the command line's words as the page's: flags as labels, SI values in the units chosen
  // (those of the field ``name`` the message is about, where given)
  const short = (f) => f.label.replace(/\s*\(.*\)$/, "");
  const NUM = "(-?(?:\\d+\\.?\\d*|\\.\\d+)(?:e[+-]?\\d+)?)";
  function inWords(text, name) {
    const own = name && fields[name] && SI_UNIT[fields[name].kind] ? fields[name] : null;
    const conv = (num, unit) => { // an SI value in the field's unit, else in its kind's on this page
      if (own && SI_UNIT[own.kind] === unit) {
        const [u, factor] = unitOf(own.name);
        return `${fmt(parseFloat(num) / factor)} ${u}`;
      }
      const kind = Object.keys(SI_UNIT).find((k) => SI_UNIT[k] === unit && unitOfKind(k)[0]);
      return kind ? qty(parseFloat(num), kind) : `${num} ${unit}`;
    };
    let t = text.replace(/\s*\(linecontact takes SI units[^)]*\)/g, "");
    t = t.replace(new RegExp(`(--[A-Za-z][\\w-]*)\\s*(?:=\\s*)?${NUM}\\s+(m|Pa|J/m\\^2|N/m)\\b`, "g"), (all, flag, num, unit) => {
      const f = fields[flagName(flag)];
      if (!f || SI_UNIT[f.kind] !== unit) return all;
      const [u, factor] = unitOf(f.name);
      return `${short(f)} = ${fmt(parseFloat(num) / factor)} ${u}`;
    });
    t = t.replace(new RegExp(`\\[${NUM}, ${NUM}\\] (m|Pa|J/m\\^2|N/m)\\b`, "g"), (all, a, b, unit) => {
      const [ca, cb] = [conv(a, unit), conv(b, unit)];
      return `[${ca.split(" ")[0]}, ${cb}]`;
    });
    t = t.replace(new RegExp(`(^|[^\\w.])${NUM} (m|Pa|J/m\\^2|N/m)\\b`, "g"), (all, pre, num, unit) => pre + conv(num, unit));
    if (own) { // "got -1000000.0": a value the field sent, in its unit
      const sent = (parse(own).values || []).map(Number);
      const same = (x) => sent.some((v) => Math.abs(v - x) <= 1e-9 * Math.abs(v));
      t = t.replace(new RegExp(`\\bgot ${NUM}(?=$|[^\\w.])`, "g"), (all, num) => (same(parseFloat(num)) ? `got ${conv(num, SI_UNIT[own.kind])}` : all));
    }
    t = t.replace(/(--[A-Za-z][\w-]*) \/ (--[A-Za-z][\w-]*) must be in \[([^\]]+)\] \(the domain of the solvers\)/g,
      (all, a, b, range) => {
        const [fa, fb] = [fields[flagName(a)], fields[flagName(b)]];
        return `the ratio ${fa ? short(fa) : a} / ${fb ? short(fb) : b} must be within [${range}] (the solvers' domain)`;
      });
    t = t.replace(/is (--[A-Za-z][\w-]*) in metres\?/g, (all, flag) => {
      const f = fields[flagName(flag)];
      return f ? `is the ${short(f)} in ${unitOf(f.name)[0]}?` : all;
    });
    t = t.replace(/(--[A-Za-z][\w-]*) \[(m|Pa|J\/m\^2|N\/m)\]/g, (all, flag, unit) => {
      const f = fields[flagName(flag)];
      return f && SI_UNIT[f.kind] === unit ? `the ${short(f)} (in ${unitOf(f.name)[0]})` : all;
    });
    t = t.replace(/--[A-Za-z][\w-]*/g, (flag) => {
      const f = fields[flagName(flag)];
      return f ? `the ${short(f)}` : flag.replace(/^--/, "").replace(/-/g, " ");
    });
    return t.replace(/\bthe the\b/g, "the").replace(/^the /, "The ");
  }
  // the field a message is about: the one it asks about ("is --z0 in metres?"), else its parameter
  function fieldOf(message, parameter) {
    const asked = /is (--[A-Za-z][\w-]*) in /.exec(message || "");
    for (const name of [asked && flagName(asked[1]), parameter, ...((message || "").match(/--[A-Za-z][\w-]*/g) || []).map(flagName)]) {
      if (name && fields[name] && $("m-" + name) && active(fields[name])) return name;
    }
    return parameter === "data" && $("m-data") ? "data" : null;
  }
  function say(name, text, kind) {
    const box = $("m-" + name);
    box.textContent = box.textContent ? box.textContent + " " + text : text;
    box.className = "message " + kind;
    const el = $("f-" + name);
    if (kind === "error" && el) el.classList.add("invalid");
  }
  function error(doc) {
    const e = (doc && doc.error) || { message: "the server gave no answer" };
    const name = fieldOf(e.message, e.parameter);
    let text = inWords(e.message || "", name);
    if (name && name !== "data") {
      const [u] = unitOf(name);
      const typed = $("f-" + name).value.trim();
      if (typed && !chosen(fields[name])) text += ` (you typed ${typed}${u ? " " + u : ""})`;
      say(name, text, "error");
    } else if (name === "data") {
      say("data", text, "error");
    } else {
      $("form-error").textContent = text;
    }
    $("answer").textContent = "";
  }

  // ---------------------------------------------------------------------------------------
  // the answer: in words, the warnings, then the full table behind a toggle

  function p(...parts) {
    const el = document.createElement("p");
    for (const x of parts) el.append(x);
    return el;
  }
  function items(list) {
    const ul = document.createElement("ul");
    for (const parts of list) {
      const li = document.createElement("li");
      for (const x of parts) li.append(x);
      ul.appendChild(li);
    }
    return ul;
  }
  const rec = (doc, i = 0) => (doc.results || [])[i] || {};
  const totalOn = (r, key, L) => (L && Number.isFinite(r[key]) ? [" (", val(key, r[key], newtons(Math.abs(r[key]))), ` on ${qty(L, "length", ["length"])})`] : []);
  const lengthOf = (doc) => (doc.parameters || {}).length_m;

  function regime(lam) {
    return lam < 0.1 ? "rigid-like (DMT): the adhesion acts outside the contact"
      : lam > 5 ? "JKR-like: a compliant contact, the adhesion at its edge"
      : "between DMT and JKR (the Maugis-Dugdale transition)";
  }
  function maugis(lam) {
    const out = p(`Maugis parameter `, val("maugis_parameter", lam, fmt(lam)), `: ${regime(lam)}.`);
    out.id = "regime";
    out.dataset.key = "maugis_parameter";
    out.dataset.value = String(lam);
    return out;
  }

  const HEADLINES = {
    pulloff(doc) {
      const r = rec(doc), L = lengthOf(doc);
      return [
        p("It comes off at a pull of ", val("F_pulloff_N_per_m", r.F_pulloff_N_per_m, qty(Math.abs(r.F_pulloff_N_per_m), "force")),
          ...totalOn(r, "F_pulloff_total_N", L), `, by the ${r.mechanism} mechanism; the contact half-width at pull-off is `,
          val("a_at_pulloff_m", r.a_at_pulloff_m, qty(r.a_at_pulloff_m, "length", ["radius"])),
          `. (The records give the pull-off force as ${fmt(r.F_pulloff_N_per_m)} N/m: a tensile load is negative.)`),
        maugis(r.maugis_parameter),
      ];
    },
    sphere(doc) {
      const r = rec(doc);
      return [
        p("It comes off at a pull of ", val("F_pulloff_N", r.F_pulloff_N, newtons(Math.abs(r.F_pulloff_N))),
          `, by the ${r.mechanism} mechanism (${fmt(r.F_pulloff_over_piwR)} pi w R; JKR: -1.5, DMT: -2); the contact radius at pull-off is `,
          val("a_at_pulloff_m", r.a_at_pulloff_m, qty(r.a_at_pulloff_m, "length", ["radius"])),
          `. (The records give the pull-off force as ${fmt(r.F_pulloff_N)} N: a tensile load is negative.)`),
        maugis(r.maugis_parameter),
      ];
    },
    "sphere-contact"(doc) {
      const rs = doc.results || [];
      const list = rs.map((r) => [`under F = `, val("F_N", r.F_N, newtons(r.F_N)), ": a = ",
        val("a_m", r.a_m, qty(r.a_m, "length", ["radius"])), ", approach ", val("delta_m", r.delta_m, qty(r.delta_m, "length", ["z0", "h"]))]);
      return [p("The contact radius a:"), items(list)];
    },
    "sphere-curve"(doc) {
      const rs = doc.results || [];
      const r = rs.find((x) => x.pull_off_load === true) || rs.reduce((m, x) => (!m || x.F_N < m.F_N ? x : m), null) || {};
      return [p("It comes off at a pull of ", val("F_N", r.F_N, newtons(Math.abs(r.F_N))), " (load control), at a contact radius a = ",
        val("a_m", r.a_m, qty(r.a_m, "length", ["radius"])), `; the curve has ${rs.length} points.`)];
    },
    "sphere-lennard-jones"(doc) {
      const r = rec(doc), mu = (doc.parameters || {}).tabor_parameter;
      return [
        p("Under the Lennard-Jones law it comes off at a pull of ", val("F_pulloff_N", r.F_pulloff_N, newtons(Math.abs(r.F_pulloff_N))),
          ` (${fmt(r.F_pulloff_over_piwR)} pi w R, within ${fmt(r.error_estimate)}; rigid: -2, JKR: -1.5; Tabor's parameter `,
          val("tabor_parameter", mu, fmt(mu)), `, solved by the ${r.method} method; the records give the pull-off force as ${fmt(r.F_pulloff_N)} N: a tensile load is negative).`),
        maugis(r.maugis_parameter),
      ];
    },
    "sphere-lennard-jones-curve"(doc) {
      const rs = doc.results || [], q = doc.parameters || {};
      const jump = Number.isFinite(q.F_jump_in_N) ? [", and jumps in at ", val("F_jump_in_N", q.F_jump_in_N, newtons(Math.abs(q.F_jump_in_N)))] : [", without a jump-in (the curve is not S-shaped)"];
      return [p("It comes off at a pull of ", val("F_pulloff_N", q.F_pulloff_N, newtons(Math.abs(q.F_pulloff_N))),
        " (load control, on the curve's mesh)", ...jump, `; the curve has ${rs.length} states (Tabor's parameter `,
        val("tabor_parameter", q.tabor_parameter, fmt(q.tabor_parameter)), ").")];
    },
    "lennard-jones"(doc) {
      const r = rec(doc);
      return [
        p("Under the Lennard-Jones law it comes off at a pull of ", val("F_pulloff_N_per_m", r.F_pulloff_N_per_m, qty(Math.abs(r.F_pulloff_N_per_m), "force")),
          ` (the law's parameter mu = `, val("mu", r.mu, fmt(r.mu)), `, solved by the ${r.method} method; the records give the pull-off force as ${fmt(r.F_pulloff_N_per_m)} N/m: a tensile load is negative).`),
        maugis(r.maugis_parameter),
      ];
    },
    contact(doc) {
      const rs = doc.results || [];
      const list = rs.map((r, i) => [`under F = `, val("F_N_per_m", r.F_N_per_m, qty(r.F_N_per_m, "force", ["load"])), ": a = ",
        val("a_m", r.a_m, qty(r.a_m, "length", ["radius"])), r.stable === false ? " (unstable branch)" : ""]);
      return [p("The contact half-width a:"), items(list)];
    },
    curve(doc) {
      const rs = doc.results || [];
      let r = rs.find((x) => x.pulloff === true);
      if (!r) r = rs.reduce((m, x) => (Number.isFinite(x.F_N_per_m) && (!m || x.F_N_per_m < m.F_N_per_m) ? x : m), null) || {};
      return [p("The most tensile load it holds (the pull-off) is ", val("F_N_per_m", r.F_N_per_m, qty(r.F_N_per_m, "force")),
        ", at a contact half-width a = ", val("a_m", r.a_m, qty(r.a_m, "length", ["radius"])), `; the curve has ${rs.length} points.`)];
    },
    cycle(doc) {
      const rs = doc.results || [];
      return [p("The energy lost per cycle, per length of wire:"), items(rs.map((r) => ["at an amplitude T* = ",
        val("T_amplitude_N_per_m", r.T_amplitude_N_per_m, qty(r.T_amplitude_N_per_m, "force", ["tangential_amplitude"])), ": W = ",
        val("W_J_per_m", r.W_J_per_m, qty(r.W_J_per_m, "energy")), r.state ? ` (${r.state})` : ""]))];
    },
    push(doc) {
      const rs = doc.results || [];
      const L = lengthOf(doc);
      const lk = ["height", "tip_height", "radius"];
      const words = { roll: "rolls first", slide: "slides first", "roll+slide": "rolls and slips at once", "lift-off": "lifts off first" };
      const list = rs.map((r) => {
        const first = r.first_motion;
        const key = first === "slide" ? "Q_slide_N_per_m" : "Q_roll_N_per_m";
        const Q = r[key];
        const total = L && Number.isFinite(Q) ? ` (${newtons(Q * L)} on ${qty(L, "length", ["length"])})` : "";
        const other = first === "slide" ? ["; rolling would take ", val("Q_roll_N_per_m", r.Q_roll_N_per_m, qty(r.Q_roll_N_per_m, "force", ["push", "load"]))]
          : ["; sliding would take ", val("Q_slide_N_per_m", r.Q_slide_N_per_m, qty(r.Q_slide_N_per_m, "force", ["push", "load"]))];
        const state = r.state ? [`; under the push given it is at `, val("state", r.state, r.state === "rest" ? "rest" : `${r.state}`)] : [];
        const at = first === "lift-off" ? [] : [" at ", val(key, Q, qty(Q, "force", ["push", "load"])), total];
        return [`at H = `, val("H_m", r.H_m, qty(r.H_m, "length", lk)), ": it ", val("first_motion", first, words[first] || first), ...at, ...other, ...state];
      });
      const out = [];
      if (rs.length === 1) out.push(p("It ", ...list[0].slice(3), ` (pushed at H = ${qty(rs[0].H_m, "length", lk)}).`));
      else out.push(p("Pushed sideways, the wire:"), items(list));
      const Hc = rs.length ? rs[0].H_critical_m : NaN;
      if (Number.isFinite(Hc) && rs.every((r) => r.H_critical_m === Hc)) {
        out.push(p("It rolls first above H* = ", val("H_critical_m", Hc, qty(Hc, "length", lk)), " and slides first below it (H* = R Δw / Q_slide)."));
      }
      return out;
    },
    "bent-wire"(doc) {
      const r = rec(doc), q = doc.parameters || {};
      const held = q.model === "held"; // a wire held at rest: f is the mean |f_n| along it
      const f = (si) => fmt(si / 1e-3) + " nN/µm"; // = mN/m
      const finite = (k) => Array.isArray(r[k]) && r[k].length === 2 && r[k].every(Number.isFinite);
      const ci = (k, unit) => (finite(k) ? [val(k, r[k], `${unit(r[k][0]).split(" ")[0]} to ${unit(r[k][1])}`)] : ["—"]);
      const boot = finite("friction_per_length_bootstrap_ci95_N_per_m")
        ? [`; the bootstrap's, from ${q.bootstrap} refits: `, ...ci("friction_per_length_bootstrap_ci95_N_per_m", f)] : [];
      const name = held ? "mean |f_n|" : "f";
      const out = [p(held ? "The static friction holding the wire, averaged along it: mean |f_n| = " : "The friction per unit length f = ",
        val("friction_per_length_N_per_m", r.friction_per_length_N_per_m, f(r.friction_per_length_N_per_m)),
        " (95 % interval ", ...ci("friction_per_length_ci95_N_per_m", f), ...boot, ").")];
      const nm = (si) => fmt(si / 1e-9) + " nm";
      const modes = held ? [`, with ${r.modes} curvature mode${r.modes === 1 ? "" : "s"} (as Schwarz's criterion chose them; f_n along the wire is plotted below)`] : [];
      out.push(p(`Fitted to ${r.points} points`, ...modes, ": the wire's half-length l = ", val("half_length_m", r.half_length_m, qty(r.half_length_m, "length", ["radius"])),
        `, the friction group ${name} l³/EI = `, val("friction_group", r.friction_group, fmt(r.friction_group)), ", the position noise ",
        val("noise_m", r.noise_m, nm(r.noise_m)), current && current.values.noise
          ? ` (as given; the residuals' estimate ${nm(r.noise_estimated_m)})` : " (the residuals' estimate)", "."));
      if (Number.isFinite(r.tau0_Pa)) {
        out.push(p(`The interfacial shear strength tau0 = ${name}/(2a) = `, val("tau0_Pa", r.tau0_Pa, qty(r.tau0_Pa, "stress")),
          " (95 % interval ", ...ci("tau0_ci95_Pa", (x) => qty(x, "stress")), "), over a contact half-width a = ",
          val("contact_half_width_m", r.contact_half_width_m, nm(r.contact_half_width_m)), "."));
      } else {
        out.push(p(`tau0 = ${name}/(2a) is not computed: it needs the contact's half-width a, from the work of adhesion w, z0 and the substrate (choose them under “tau0 = f/(2a)” above).`));
      }
      const note = (r.note || "").split("; ").filter((x) => x && !x.startsWith("tau0 needs"));
      if (note.length || r.determined === false) {
        const words = inWords(note.join("; ") || `the data do not determine ${name}`);
        const said = p(r.determined === false ? "Beware: " + words[0].toLowerCase() + words.slice(1) : words, ".");
        said.id = "bent-wire-note";
        out.push(said);
      }
      return out;
    },
    fit(doc) {
      const r = rec(doc);
      const ci = (k, kind) => (Array.isArray(r[k]) ? ` (95 % interval ${qty(r[k][0], kind, ["z0"])} to ${qty(r[k][1], kind, ["z0"])})` : "");
      const fixed = (doc.parameters || {}).z0_fixed;
      const out = [p("The work of adhesion w = ", val("work_of_adhesion", r.work_of_adhesion, qty(r.work_of_adhesion, "work")), ci("work_of_adhesion_ci95", "work"),
        fixed ? ", with z0 fixed at " : "; the range z0 = ", val("z0", r.z0, qty(r.z0, "length", ["z0"])), fixed ? "" : ci("z0_ci95", "length"), ".")];
      if (r.note) out.push(p(inWords(r.note).replace(/Fix equilibrium_spacing/, "Fix z0 (its field above)")));
      return out;
    },
  };

  // the map at your wire: which models hold on the map's column nearest its Maugis parameter
  function mapAtWire(doc, lam) {
    const recs = (doc.results || []).filter((r) => Number.isFinite(r.maugis_parameter));
    if (!recs.length || !Number.isFinite(lam)) return [];
    const near = recs.reduce((m, r) => (Math.abs(Math.log(r.maugis_parameter / lam)) < Math.abs(Math.log(m / lam)) ? r.maugis_parameter : m), recs[0].maugis_parameter);
    const col = recs.filter((r) => r.maugis_parameter === near);
    const names = { md: "Maugis-Dugdale", jkr: "JKR", hertz: "Hertz", rigid: "the rigid cylinder" };
    const parts = Object.entries(names).map(([k, n]) => `${n} at ${col.filter((r) => r[`agrees_${k}`] === true).length}`);
    const out = p(`On the map's column nearest your wire (Maugis parameter `, val("maugis_parameter", near, fmt(near)),
      `), the models give the full law's contact width within the tolerance at these of its ${col.length} loads: ${parts.join(", ")}.`);
    out.id = "map-at-wire";
    return [out];
  }

  function headline(doc, mark) {
    const box = $("answer");
    box.textContent = "";
    const fn = HEADLINES[spec.page];
    const head = document.createElement("div");
    head.id = "headline";
    if (fn) for (const el of fn(doc)) head.appendChild(el);
    if (mark) for (const el of mark.head) head.appendChild(el);
    if (mark && spec.page === "map") for (const el of mapAtWire(doc, mark.x)) head.appendChild(el);
    box.appendChild(head);
  }

  function warnings(list) {
    const said = [...new Set(list || [])];
    if (!said.length) return;
    const box = document.createElement("div");
    box.id = "warnings";
    box.className = "warnings";
    const h = document.createElement("h2");
    h.textContent = said.length === 1 ? "A warning" : `${said.length} warnings`;
    const ul = document.createElement("ul");
    for (const w of said) {
      const li = document.createElement("li");
      li.textContent = inWords(w);
      li.dataset.raw = w;
      ul.appendChild(li);
      const name = fieldOf(w, null);
      if (name) say(name, "Warning: " + inWords(w, name), "warn");
    }
    box.append(h, ul);
    $("answer").appendChild(box);
  }

  // the table: SI values first, then words, then the groups and diagnostics; 5 digits shown
  function cell(key, v) {
    const td = document.createElement("td");
    td.dataset.key = key;
    td.dataset.value = v === null ? "null" : typeof v === "object" ? JSON.stringify(v) : String(v);
    td.textContent = v === null ? "—" : typeof v === "number" ? fmt(v, 5)
      : Array.isArray(v) ? (v.length > 8 ? `${v.length} values (in the JSON and CSV)` : v.map((x) => fmt(x, 5)).join(", "))
      : typeof v === "object" ? JSON.stringify(v) : String(v);
    return td;
  }
  function results(doc) {
    const box = $("results");
    box.textContent = "";
    const recs = doc.results || [];
    const units = doc.units || {};
    let keys = [];
    for (const r of recs) for (const k of Object.keys(r)) if (!keys.includes(k)) keys.push(k);
    const rank = (k) => (units[k] && units[k] !== "1" ? 0 : recs.some((r) => typeof r[k] === "string") ? 1 : 2);
    keys = keys.map((k, i) => [rank(k), i, k]).sort((a, b) => a[0] - b[0] || a[1] - b[1]).map((x) => x[2]);
    const wrap = document.createElement("div");
    wrap.className = "scroll";
    const t = document.createElement("table");
    const head = t.createTHead().insertRow();
    for (const k of keys) {
      const th = document.createElement("th");
      const unit = units[k];
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
    h.textContent = "Results (SI units)";
    box.append(h, wrap);
    const dl = document.createElement("dl");
    dl.className = "parameters";
    for (const [k, v] of Object.entries(doc.parameters || {})) {
      const dt = document.createElement("dt");
      dt.textContent = k;
      const dd = document.createElement("dd");
      dd.dataset.key = k;
      dd.dataset.value = typeof v === "object" ? JSON.stringify(v) : String(v);
      dd.textContent = typeof v === "number" ? fmt(v, 5) : typeof v === "object" ? JSON.stringify(v) : String(v);
      dl.append(dt, dd);
    }
    const h2 = document.createElement("h2");
    h2.textContent = "Parameters";
    box.append(h2, dl);
  }

  // ---------------------------------------------------------------------------------------
  // plots: layers of points, lines and bands in the units chosen

  const NS = "http://www.w3.org/2000/svg";
  const COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"];

  // layers: [{label, pts: [[x, y, flag]], line, points, dash, color, band: [[x, y0, y1]]}]
  function plot(layers, P, mark, figId = "plot", svgId = "plot-svg") {
    const fig = $(figId);
    fig.textContent = "";
    const all = [];
    for (const l of layers) {
      for (const q of l.pts || []) if (Number.isFinite(q[0]) && Number.isFinite(q[1])) all.push(q);
      for (const q of l.band || []) if (Number.isFinite(q[0]) && Number.isFinite(q[1]) && Number.isFinite(q[2])) all.push([q[0], q[1]], [q[0], q[2]]);
    }
    if (!all.length) return;
    const W = 640, H = 360, L = 78, B = 45, T = 15, R = 15;
    let [x0, x1] = [Math.min(...all.map((q) => q[0])), Math.max(...all.map((q) => q[0]))];
    let [y0, y1] = [Math.min(...all.map((q) => q[1])), Math.max(...all.map((q) => q[1]))];
    if (P.yzero) { y0 = Math.min(y0, 0); y1 = Math.max(y1, 0); }
    if (x0 === x1) { x0 -= Math.abs(x0) * 0.1 || 1; x1 += Math.abs(x1) * 0.1 || 1; }
    if (y0 === y1) { y0 -= Math.abs(y0) * 0.1 || 1; y1 += Math.abs(y1) * 0.1 || 1; }
    const pad = (y1 - y0) * 0.05;
    y0 -= pad; y1 += pad;
    if (P.equal) { // equal scales: the shorter range widened about its middle
      const per = Math.max((x1 - x0) / (W - L - R), (y1 - y0) / (H - B - T));
      const [cx, cy] = [(x0 + x1) / 2, (y0 + y1) / 2];
      [x0, x1] = [cx - per * (W - L - R) / 2, cx + per * (W - L - R) / 2];
      [y0, y1] = [cy - per * (H - B - T) / 2, cy + per * (H - B - T) / 2];
    }
    const view = { x0, x1, y0, y1 };
    const svg = document.createElementNS(NS, "svg");
    svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
    svg.setAttribute("role", "img");
    svg.setAttribute("aria-label", `${P.ylabel} against ${P.xlabel}`);
    svg.setAttribute("id", svgId);
    function draw() {
      svg.textContent = "";
      const sx = (x) => L + (x - view.x0) / (view.x1 - view.x0) * (W - L - R);
      const sy = (y) => H - B - (y - view.y0) / (view.y1 - view.y0) * (H - B - T);
      const add = (tag, attrs, text, parent = svg) => {
        const e = document.createElementNS(NS, tag);
        for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
        if (text !== undefined) e.textContent = text;
        parent.appendChild(e);
        return e;
      };
      add("rect", { x: 0, y: 0, width: W, height: H, fill: "white" });
      add("line", { x1: L, y1: H - B, x2: W - R, y2: H - B, stroke: "black" });
      add("line", { x1: L, y1: T, x2: L, y2: H - B, stroke: "black" });
      for (let i = 0; i <= 4; i++) {
        const xv = view.x0 + (view.x1 - view.x0) * i / 4, yv = view.y0 + (view.y1 - view.y0) * i / 4;
        add("text", { x: sx(xv), y: H - B + 16, "text-anchor": "middle", "font-size": 11 }, fmt(xv, 3));
        add("text", { x: L - 6, y: sy(yv) + 4, "text-anchor": "end", "font-size": 11 }, fmt(yv, 3));
      }
      add("text", { x: (L + W - R) / 2, y: H - 8, "text-anchor": "middle", "font-size": 12 }, P.xlabel);
      add("text", { x: 14, y: (T + H - B) / 2, "text-anchor": "middle", "font-size": 12,
        transform: `rotate(-90 14 ${(T + H - B) / 2})` }, P.ylabel);
      const g = add("g", {});
      const clip = (q) => q[0] >= view.x0 && q[0] <= view.x1 && q[1] >= view.y0 && q[1] <= view.y1;
      layers.forEach((l, n) => {
        const color = l.color || COLORS[n % COLORS.length];
        if (l.band && l.band.length) {
          const ok = l.band.filter((q) => q.every(Number.isFinite));
          const top = ok.map((q) => `${sx(q[0])},${sy(Math.min(Math.max(q[2], view.y0), view.y1))}`);
          const bot = ok.slice().reverse().map((q) => `${sx(q[0])},${sy(Math.min(Math.max(q[1], view.y0), view.y1))}`);
          add("polygon", { points: [...top, ...bot].join(" "), fill: color, "fill-opacity": 0.18, stroke: "none", class: "band" }, undefined, g);
        }
        const pts = (l.pts || []).filter((q) => Number.isFinite(q[0]) && Number.isFinite(q[1]));
        if (l.line) {
          add("polyline", { points: pts.filter(clip).map((q) => `${sx(q[0])},${sy(q[1])}`).join(" "), fill: "none", stroke: color,
            "stroke-width": 2, "stroke-dasharray": l.dash ? "6 4" : "none", class: "series" }, undefined, g);
        }
        if (l.points === false) return;
        for (const q of pts.filter(clip)) {
          const c = add("circle", { cx: sx(q[0]), cy: sy(q[1]), r: l.line ? 3 : 4,
            fill: q[2] === false ? (P.falseColor || "#bbbbbb") : color, "data-x": q[0], "data-y": q[1] }, undefined, g);
          add("title", {}, `${l.label ? l.label + "\n" : ""}${P.xlabel} = ${fmt(q[0], 6)}\n${P.ylabel} = ${fmt(q[1], 6)}`, c);
        }
      });
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
    const legend = layers.filter((l) => l.label).map((l, n) => {
      const s = document.createElement("span");
      s.className = "key";
      s.style.setProperty("--c", l.color || COLORS[layers.indexOf(l) % COLORS.length]);
      s.textContent = l.label + (l.dash ? " (dashed)" : "") + (l.band ? " (band)" : "");
      return s;
    });
    if (legend.length > 1 || P.legend) {
      const lg = document.createElement("div");
      lg.className = "legend";
      if (P.legend) lg.append(P.legend + " ");
      if (legend.length > 1) lg.append(...legend);
      cap.appendChild(lg);
    }
    cap.append("Hover a point for its values; the wheel zooms, a double-click resets.");
    if (mark && mark.x !== undefined && !(mark.x >= x0 && mark.x <= x1)) {
      cap.append(` ${mark.label}: ${P.xlabel} ${fmt(mark.x)}, outside this map.`);
    }
    fig.appendChild(cap);
  }

  // the page's plot from its spec: x and y in the units chosen
  function axis(a, prefer) {
    const [u, f] = a.kind === "none" ? ["", 1] : unitOfKind(a.kind, prefer);
    return { f, label: a.label + (u ? ` [${u}]` : "") };
  }
  function pagePlot(doc, mark, extra) {
    const P = spec.plot;
    if (!P) return;
    const prefer = ["height", "tip_height", "load", "push", "tangential_amplitude", "radius"];
    const X = axis(P.x, prefer);
    const Ys = P.ys.map((y) => axis(y, prefer));
    const recs = doc.results || [];
    const layers = P.ys.map((y, i) => ({
      label: y.label,
      pts: recs.map((r) => [r[P.x.key] / X.f, r[y.key] / Ys[i].f, P.color ? r[P.color] : null]),
      line: !P.points,
    }));
    for (const l of extra || []) layers.push(l(X, Ys[0]));
    const ylabel = (P.ylabel || P.ys[0].label) + (Ys[0].label.match(/ \[[^\]]*\]$/) || [""])[0];
    plot(layers, { xlabel: X.label, ylabel, legend: P.legend }, mark);
  }

  // ---------------------------------------------------------------------------------------
  // the same elsewhere: the command line and the Python lines (from the SI values sent)

  function command(values, extra) {
    const words = ["linecontact", spec.command];
    for (const [k, v] of Object.entries(values)) words.push("--" + k.replace(/_/g, "-"), ...v);
    for (const [k, v] of Object.entries(spec.fixed || {})) words.push(...(v === "true" ? ["--" + k] : ["--" + k, v]));
    if (extra) words.push(...extra);
    return words.join(" ");
  }
  const one = (v, k) => (v[k] ? v[k][0] : null);
  // the Python lines are the server's: the library calls that computed the answer, written
  // as they were made (the page asks for them with "Prefer: python"; the map: its wire's)
  function equivalent(values, python) {
    $("cli").textContent = command(values, spec.upload ? ["--data", current && current.data || "measurements.csv"] : null);
    $("py").textContent = python || "";
  }
  function noEquivalent() {
    $("cli").textContent = "(the command line and the Python lines follow once the fields marked above are right)";
    $("py").textContent = "";
  }

  // ---------------------------------------------------------------------------------------
  // the page's extra requests: the map's wire, the push's flat push, the fit's curve

  const PYTHON = { headers: { Prefer: "python" } }; // the answer's Python lines too
  async function api(cmd, p, init) {
    const r = await fetch("/api/v1/" + cmd + "?" + p.toString(), init);
    const doc = await r.json().catch(() => null);
    return [r.status, doc];
  }
  function withoutPython(doc) { // the answer as the API gives it, and its Python lines
    const { python, ...rest } = doc || {};
    return [rest, python || ""];
  }

  async function marked(aux) {
    if (!spec.mark) return null;
    const [status, answer] = await api(spec.mark.command, params(aux, true), PYTHON);
    if (status !== 200) { error(answer); return null; }
    const [doc, python] = withoutPython(answer);
    const r = doc.results[0];
    const v = r[spec.mark.key];
    const head = p("Your wire: ", val(spec.mark.key, v, `Maugis parameter ${fmt(v)}`), `, ${regime(v)}; `,
      "it comes off at a pull of ", val("F_pulloff_N_per_m", r.F_pulloff_N_per_m, qty(Math.abs(r.F_pulloff_N_per_m), "force")), ".");
    head.id = "mark-value";
    head.dataset.key = spec.mark.key;
    head.dataset.value = String(v);
    return { x: v, label: spec.mark.label, head: [head], warnings: doc.warnings || [], python };
  }

  // the push of a flat pusher at the tip's heights: what the tip changes
  async function flatPush(values) {
    if (spec.page !== "push" || !values.tip_height) return [];
    const v = { ...values, height: values.tip_height };
    delete v.tip_height; delete v.tip_friction; delete v.push;
    const [status, doc] = await api("push", params(v));
    if (status !== 200) return [];
    return [
      (X, Y) => ({ label: "a flat push: to roll", dash: true, color: COLORS[0], points: false, line: true, pts: doc.results.map((r) => [r.H_m / X.f, r.Q_roll_N_per_m / Y.f]) }),
      (X, Y) => ({ label: "a flat push: to slide", dash: true, color: COLORS[1], points: false, line: true, pts: doc.results.map((r) => [r.H_m / X.f, r.Q_slide_N_per_m / Y.f]) }),
    ];
  }

  // the fit's curve and its band (w at the ends of its 95 % interval), over the radii measured
  async function fitCurve(doc, values) {
    const r = rec(doc);
    if (!Array.isArray(r.radius_m) || !r.radius_m.length) return null;
    const lo = Math.min(...r.radius_m) / 1.5, hi = Math.max(...r.radius_m) * 1.5;
    const radii = Array.from({ length: 13 }, (_, i) => lo * Math.pow(hi / lo, i / 12));
    const ci = Array.isArray(r.work_of_adhesion_ci95) ? r.work_of_adhesion_ci95 : [r.work_of_adhesion, r.work_of_adhesion];
    const at = async (R, w) => {
      const q = params({ cylinder_material: values.cylinder_material, substrate_material: values.substrate_material,
        radius: [siText(R)], work_of_adhesion: [siText(w)], z0: [siText(r.z0)] }, true);
      const [status, d] = await api("pulloff", q);
      return status === 200 ? d.results[0].F_pulloff_N_per_m : NaN;
    };
    const rows = await Promise.all(radii.map(async (R) => [R, await at(R, r.work_of_adhesion), await at(R, ci[0]), await at(R, ci[1])]));
    return rows;
  }
  function fitPlot(doc, rows) {
    const r = rec(doc);
    const X = axis({ kind: "length", label: "radius R" }, ["z0"]);
    const Y = axis({ kind: "force", label: "pull-off force" }, []);
    const layers = [{ label: "measured", pts: r.radius_m.map((R, i) => [R / X.f, r.pull_off_force_N_per_m[i] / Y.f]) }];
    if (rows) {
      layers.push({ label: "the fit", line: true, points: false, pts: rows.map((q) => [q[0] / X.f, q[1] / Y.f]), color: COLORS[1],
        band: rows.map((q) => [q[0] / X.f, Math.min(q[2], q[3]) / Y.f, Math.max(q[2], q[3]) / Y.f]) });
    }
    plot(layers, { xlabel: X.label, ylabel: Y.label, legend: rows ? "band: w at the ends of its 95 % interval, z0 at its fit;" : "" });
  }

  // the bent wire's profile and the fitted wire over it in the wire's frame, as the library's
  // figure draws them (figures/bent_wire): from the fitted midpoint, along the axis (angle a)
  // and across it towards the drag (angle d; the held wire: a + pi/2). A dragged wire, bent
  // by tens of nm over µm, looks straight at equal scales: its transverse scale is
  // exaggerated; the held wire, bent much, is drawn at equal scales. Below, the residuals
  // against the arc length from the midpoint with the band of +-2 noises; for the held wire,
  // the friction normal to it, f_n, along it with its band of +-2 sd
  function bentPlot(doc) {
    const r = rec(doc), held = (doc.parameters || {}).model === "held";
    const fnFig = $("normal-friction");
    if (fnFig) fnFig.textContent = "";
    if (!Array.isArray(r.x_m) || !r.x_m.length || !Array.isArray(r.curve_x_m) || !Array.isArray(r.midpoint_m)) return;
    const a = r.axis_angle, d = Number.isFinite(r.drag_angle) ? r.drag_angle : a + Math.PI / 2;
    const [mx, my] = r.midpoint_m;
    const frame = (x, y) => [(x - mx) * Math.cos(a) + (y - my) * Math.sin(a), (x - mx) * Math.cos(d) + (y - my) * Math.sin(d)];
    const pts = r.x_m.map((x, i) => frame(x, r.y_m[i])), wire = r.curve_x_m.map((x, i) => frame(x, r.curve_y_m[i]));
    const all = [...pts, ...wire, [0, 0]];
    const range = (j) => Math.max(...all.map((q) => q[j])) - Math.min(...all.map((q) => q[j]));
    const [u, k] = Math.max(range(0), range(1)) < 1e-4 ? ["nm", 1e-9] : ["µm", 1e-6];
    const layers = [
      { label: "the profile (data)", pts: pts.map((q) => [q[0] / k, q[1] / k]) },
      { label: "the fitted wire", line: true, points: false, color: COLORS[1], pts: wire.map((q) => [q[0] / k, q[1] / k]) },
      { label: "its midpoint", color: COLORS[2], pts: [[0, 0]] },
    ];
    let scale = "Equal scales along and across (the residuals below show the fit's detail);";
    if (!held) { // the transverse scale's exaggeration: the lengths per pixel, along over across
      const AREA = [547, 300]; // plot()'s drawing area [px]: W - L - R by H - B - T
      const factor = (range(0) / AREA[0]) / (range(1) * 1.1 / AREA[1]); // plot() pads y by 5 % each side
      scale = factor >= 1.05 ? `The transverse scale is exaggerated ×${fmt(factor, 3)} (a wire bent this little looks straight at equal scales);`
        : factor > 1 / 1.05 ? "Nearly equal scales along and across;"
        : `The transverse scale is ×${fmt(factor, 2)} the axial;`;
    }
    plot(layers, { xlabel: `along the wire's axis [${u}]`, ylabel: held ? `across it [${u}]` : `across it, towards the drag [${u}]`,
      equal: held, legend: `In the wire's frame, from its midpoint. ${scale}` });
    if (!Array.isArray(r.residuals_m) || !Array.isArray(r.arc_length_m)) return;
    const two = 2 * r.noise_m / 1e-9, ends = [-r.half_length_m / k, r.half_length_m / k];
    plot([
      { label: `±2 noises (±${fmt(two)} nm)`, pts: [], band: ends.map((x) => [x, -two, two]), color: COLORS[1] },
      { label: "residuals", pts: r.arc_length_m.map((x, i) => [x / k, r.residuals_m[i] / 1e-9]), color: COLORS[0] },
    ], { xlabel: `arc length from the midpoint [${u}]`, ylabel: "residual [nm]",
      legend: "Each point's signed distance to the fitted wire: noise leaves about 95 % inside the band and no long runs of one sign;" },
    null, "residuals", "residuals-svg");
    const fn = r.normal_friction_N_per_m, sd = r.normal_friction_sd_N_per_m, s = r.curve_arc_length_m;
    if (!held || !fnFig || !Array.isArray(fn) || !Array.isArray(s) || !Array.isArray(sd)) return;
    const F = 1e-3; // N/m -> nN/µm
    plot([
      { label: "±2 sd", pts: [], band: s.map((x, i) => [x / k, (fn[i] - 2 * sd[i]) / F, (fn[i] + 2 * sd[i]) / F]), color: COLORS[1] },
      { label: "f_n = EI(κ'' + κ³/2)", line: true, points: false, pts: s.map((x, i) => [x / k, fn[i] / F]), color: COLORS[1] },
    ], { xlabel: `arc length from the midpoint [${u}]`, ylabel: "f_n [nN/µm]",
      legend: `The static friction normal to the wire along it (its mean |f_n|, ${fmt(r.friction_per_length_N_per_m / F)} nN/µm, is the headline's);` },
    null, "normal-friction", "normal-friction-svg");
  }

  // the motion map of the pushed wire: first motion over push height and friction stress
  async function motion(values) {
    const fig = $("motion");
    fig.textContent = "";
    if (spec.page !== "push" || values.tip_height) return;
    const R = parseFloat(one(values, "radius")), tau = parseFloat(one(values, "tau0"));
    if (!(R > 0 && tau > 0)) return;
    const hs = Array.from({ length: 21 }, (_, i) => siText(2 * R * i / 20));
    const pts = [];
    const X = axis({ kind: "length", label: "push height H" }, ["height", "radius"]);
    const mine = generation;
    for (const f of [0.01, 0.03, 0.1, 0.3, 1, 3, 10, 30, 100]) {
      if (mine !== generation) return; // a newer computation was asked for
      const v = { ...values, tau0: [siText(tau * f)], height: hs };
      delete v.push;
      const [status, doc] = await api("push", params(v));
      if (status !== 200) continue;
      for (const r of doc.results) pts.push([r.H_m / X.f, Math.log10(tau * f), r.first_motion === "roll"]);
    }
    if (mine !== generation) return;
    plot([{ pts, label: "" }], { xlabel: X.label, ylabel: "log10 tau0 [Pa]", falseColor: "#ff7f0e",
      legend: "The motion map: blue rolls first, orange slides first (or rolls and slips);" },
    { y: Math.log10(tau), label: "your wire" }, "motion", "motion-svg");
  }

  // ---------------------------------------------------------------------------------------
  // downloads

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

  // ---------------------------------------------------------------------------------------
  // computing

  let current = null; // the inputs of the computation shown
  let generation = 0; // counts the computations asked for: older extra requests stop
  async function done(answer) {
    const [doc, python] = withoutPython(answer);
    const mine = generation;
    const { values, aux } = current;
    const mark = await marked(aux);
    if (mine !== generation) return; // a newer computation was asked for
    const file = spec.upload && $("f-data").files[0];
    current.data = (doc.parameters || {}).data || (file && file.name); // the file as the user named it
    equivalent(values, python || (mark && mark.python)); // with the answer, not after its plot
    headline(doc, mark);
    warnings([...(doc.warnings || []), ...((mark && mark.warnings) || [])]);
    if (spec.page === "fit") fitPlot(doc, null);
    else if (spec.page === "bent-wire") bentPlot(doc);
    else {
      const extra = await flatPush(values);
      if (mine !== generation) return;
      pagePlot(doc, mark, extra);
    }
    results(doc);
    downloads(doc);
    $("status").textContent = `done: ${(doc.results || []).length} record(s)`;
    if (spec.page === "fit") {
      const rows = await fitCurve(doc, values);
      if (mine !== generation) return;
      fitPlot(doc, rows);
      downloads(doc);
    }
    motion(values);
  }

  async function poll(id, mine) {
    const r = await fetch("/api/v1/jobs/id/" + id);
    const doc = await r.json();
    if (mine !== generation) return; // a newer computation was asked for
    if (doc.state === "queued" || doc.state === "running") {
      const pr = doc.progress ? `${doc.progress.done}/${doc.progress.total} curves, ` : "";
      const what = doc.state === "queued" ? "waiting for a worker..." : "computing...";
      $("status").textContent = `${what} ${pr}${doc.elapsed_s.toFixed(1)} s`;
      job = setTimeout(() => poll(id, mine), 500);
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
    generation += 1;
    if (job) { clearTimeout(job); job = null; }
    clearMessages();
    for (const id of ["answer", "plot", "motion", "residuals", "normal-friction", "results", "downloads"]) if ($(id)) $(id).textContent = "";
    const main = inputs(false), aux = inputs(true);
    const errors = { ...main.errors, ...aux.errors };
    if (Object.keys(errors).length) { // nothing computed with a number the user did not mean
      for (const [name, text] of Object.entries(errors)) say(name, text, "error");
      $("status").textContent = "";
      noEquivalent();
      return;
    }
    current = { values: main.values, aux: aux.values };
    const p = params(main.values);
    const link = new URLSearchParams([...p.entries(), ...params(aux.values, true).entries()]);
    for (const f of spec.fields) {
      const u = $("u-" + f.name);
      if (u && active(f) && (main.values[f.name] || aux.values[f.name]) && u.selectedIndex > 0) link.append("u." + f.name, u.value);
    }
    history.replaceState(null, "", location.pathname + "?" + link.toString());
    equivalent(main.values, "");
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
        poll(doc.id, generation);
        return;
      }
      if (spec.upload) {
        const fd = new FormData();
        for (const [k, v] of p.entries()) fd.append(k, v);
        const file = $("f-data").files[0];
        if (file) fd.append("data", file);
        r = await fetch("/api/v1/" + spec.command, { method: "POST", body: fd, ...PYTHON });
      } else {
        r = await fetch("/api/v1/" + spec.command + "?" + p.toString(), PYTHON);
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

  const clean = fill();
  if (clean && [...new URLSearchParams(location.search).keys()].some((k) => k in fields)) form.requestSubmit();
})();
