// The shot lab in a real browser: headless Chromium (Debian's /usr/bin/chromium) driven by
// playwright-core. Starts `snooker serve --port 0`, then: loads the page, drags a ball, aims by
// dragging on the cloth, strikes, and checks the drawn paths against `snooker simulate` of the
// scene the page downloads (numbers, not pixels: every event position of the command's JSON is
// a vertex of the drawn path, to the bit, and every ball ends where the command says); checks
// the JSON result downloaded is the command's bytes; shows a bad scene's error as the command
// says it; plans a shot (picked on the table), cancels a plan, plays the planned shot; plays a
// stroke of a frame with the referee; lets the player play a visit (its reasoning checked against
// the server's JSON, the scores against the referee's), then starts a frame against the player
// and cancels its visit while it thinks, and sees its visit start by itself after a stroke
// played by hand gives it the table. Fails on any
// console error, page error or request off the local server.
//
//   SNOOKER_BIN=target/ci/snooker node server/browser/lab.test.mjs [--screenshots DIR]

import { chromium } from "playwright-core";
import { spawn, spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, writeFileSync, mkdirSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import assert from "node:assert/strict";

const BIN = resolve(process.env.SNOOKER_BIN || "target/ci/snooker");
const CHROMIUM = process.env.CHROMIUM || "/usr/bin/chromium";
const shotsAt = process.argv.indexOf("--screenshots");
const SHOTS = shotsAt > 0 ? resolve(process.argv[shotsAt + 1]) : null;
const TMP = mkdtempSync(join(tmpdir(), "shotlab-"));
// The flags this machine's closed network needs (/work/.library/env/machines/rust.md).
const FLAGS = [
  "--no-sandbox",
  "--disable-gpu",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
];

function log(...a) {
  console.log("shotlab:", ...a);
}

// `snooker serve --port 0`: the address it prints.
function startServer() {
  return new Promise((ok, fail) => {
    const p = spawn(BIN, ["serve", "--port", "0"], { stdio: ["ignore", "inherit", "pipe"] });
    let err = "";
    const timer = setTimeout(() => fail(new Error(`no address from snooker serve: ${err}`)), 30000);
    p.stderr.on("data", (d) => {
      err += d;
      const m = /(http:\/\/127\.0\.0\.1:\d+)\//.exec(err);
      if (m) {
        clearTimeout(timer);
        ok({ proc: p, base: m[1] });
      }
    });
    p.on("exit", (code) => fail(new Error(`snooker serve exited (${code}): ${err}`)));
  });
}

function run(args, cwd = TMP) {
  const r = spawnSync(BIN, args, { cwd, encoding: "utf8" });
  return { code: r.status, out: r.stdout, err: r.stderr };
}

const { proc, base } = await startServer();
log("server at", base);
const browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: FLAGS });
const problems = [];
let expected400 = 0;
try {
  const context = await browser.newContext({ viewport: { width: 1440, height: 900 }, acceptDownloads: true });
  const page = await context.newPage();
  page.on("console", (m) => {
    if (m.type() !== "error") return;
    // The one failed request the test makes on purpose (a bad scene) is logged by the browser.
    if (expected400 > 0 && /status of 400/.test(m.text())) {
      expected400 -= 1;
      return;
    }
    problems.push(`console error: ${m.text()}`);
  });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("request", (r) => {
    const u = r.url();
    if (!u.startsWith(base + "/") && !u.startsWith("blob:") && !u.startsWith("data:")) {
      problems.push(`request off the local server: ${u}`);
    }
  });
  const shot = async (name, panel = null) => {
    if (SHOTS) {
      if (panel) await page.$eval(panel, (p) => p.scrollIntoView({ block: "start" }));
      mkdirSync(SHOTS, { recursive: true });
      await page.screenshot({ path: join(SHOTS, name) });
      log("screenshot", name);
    }
  };
  const idle = () => page.waitForSelector('body[data-animating="false"]', { timeout: 60000 });
  // Screen point of a table-frame point.
  const screen = (x, y) =>
    page.evaluate(([x, y]) => {
      const m = document.getElementById("frame").getScreenCTM();
      const p = new DOMPoint(x, y).matrixTransform(m);
      return [p.x, p.y];
    }, [x, y]);
  const drag = async (from, to) => {
    await page.mouse.move(from[0], from[1]);
    await page.mouse.down();
    await page.mouse.move(to[0], to[1], { steps: 12 });
    await page.mouse.up();
  };

  // 1. The page loads, with the cut-30 scene.
  await page.goto(base + "/");
  await page.waitForSelector('body[data-ready="true"]');
  const info = await page.evaluate(() => window.lab.info);
  assert.ok(info.layouts.length >= 3, "layouts offered");
  await shot("shotlab-start.png");

  // 2. Drag the red 4 cm along the table and 2 cm across; the scene follows the drop.
  const red0 = await page.evaluate(() => window.lab.ball("red").pos.slice());
  await drag(await screen(red0[0], red0[1]), await screen(red0[0] + 0.04, red0[1] - 0.02));
  const red1 = await page.evaluate(() => window.lab.ball("red").pos.slice());
  assert.ok(Math.abs(red1[0] - red0[0] - 0.04) < 0.003 && Math.abs(red1[1] - red0[1] + 0.02) < 0.003,
    `red dragged from ${red0} to ${red1}`);
  const drawn = await page.$eval('#balls [data-ball="red"]', (c) => [Number(c.getAttribute("cx")), Number(c.getAttribute("cy"))]);
  assert.deepEqual(drawn, red1, "the red is drawn where the scene has it");

  // 3. Aim by dragging on the cloth from behind the cue ball to 2 cm beside the red's centre
  // (a cut), a little side and screw on the face, then strike.
  const cue = await page.evaluate(() => window.lab.ball("cue").pos.slice());
  await drag(await screen(cue[0] - 0.3, cue[1] + 0.2), await screen(red1[0], red1[1] + 0.02));
  const aim = await page.evaluate(() => window.lab.strike.aim);
  const want = Math.atan2(red1[1] + 0.02 - cue[1], red1[0] - cue[0]);
  assert.ok(Math.abs(aim - want) < 0.01, `aim ${aim} towards ${want}`);
  const face = await page.$eval("#face", (f) => { const r = f.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2, r.width]; });
  await page.mouse.click(face[0] + face[2] * 0.08, face[1] + face[2] * 0.12);
  const offset = await page.evaluate(() => window.lab.strike.offset);
  assert.ok(offset[0] > 0 && offset[1] < 0, `side right, screw: ${offset}`);
  await page.click("#strike");
  await page.waitForFunction(() => window.lab.shot !== null);
  await idle();
  await shot("shotlab-strike.png");

  // 4. The drawn paths against `snooker simulate` of the same scene (downloaded from the page).
  const dl = async (button, name) => {
    const [d] = await Promise.all([page.waitForEvent("download"), page.click(button)]);
    const path = join(TMP, name);
    await d.saveAs(path);
    return path;
  };
  const sceneFile = await dl("#dl-scene", "lab-scene.toml");
  const cli = run(["simulate", sceneFile, "--json", join(TMP, "cli.json")]);
  assert.equal(cli.code, 0, `snooker simulate: ${cli.err}`);
  const cliText = readFileSync(join(TMP, "cli.json"), "utf8");
  const result = JSON.parse(cliText);
  const polylines = await page.$$eval("#paths polyline", (ps) =>
    Object.fromEntries(ps.map((p) => [p.dataset.ball, p.getAttribute("points").trim().split(/\s+/).map((s) => s.split(",").map(Number))])));
  let checked = 0;
  for (const e of result.events) {
    for (const [id, s] of Object.entries(e.after)) {
      if (s.motion === "pocketed" || s.motion === "off_table") continue;
      const pts = polylines[id];
      assert.ok(pts, `${id} moves (event ${e.kind} at ${e.t}) but has no drawn path`);
      assert.ok(pts.some(([x, y]) => x === s.pos[0] && y === s.pos[1]),
        `${id} at ${e.kind} (t=${e.t}): (${s.pos[0]}, ${s.pos[1]}) is not a vertex of its drawn path`);
      checked += 1;
    }
  }
  for (const [id, s] of Object.entries(result.final)) {
    const c = await page.$eval(`#balls [data-ball="${id}"]`, (c) => [Number(c.getAttribute("cx")), Number(c.getAttribute("cy")), c.style.visibility]);
    if (s.motion === "pocketed" || s.motion === "off_table") {
      assert.equal(c[2], "hidden", `${id} left play and is hidden`);
    } else {
      assert.deepEqual(c.slice(0, 2), s.pos.slice(0, 2), `${id} ends where snooker simulate says`);
      if (polylines[id]) assert.deepEqual(polylines[id].at(-1), s.pos.slice(0, 2), `${id}'s path ends at its final position`);
    }
  }
  assert.ok(result.events.some((e) => e.kind === "ball_ball"), "the cue ball hit the red");
  log(`drawn paths match snooker simulate: ${checked} event positions, ${Object.keys(result.final).length} final positions`);
  const listed = await page.$$eval("#events li", (l) => l.length);
  assert.equal(listed, result.events.length, "every event listed");
  // The JSON result downloaded is the command's, byte for byte.
  const pageJson = readFileSync(await dl("#dl-result", "lab-result.json"), "utf8");
  assert.equal(pageJson, cliText, "the downloaded result is snooker simulate's JSON");
  const rrd = readFileSync(await dl("#dl-recording", "lab.rrd"));
  assert.ok(rrd.length > 1000 && rrd.subarray(0, 4).toString() === "RRF2", `a Rerun recording (${rrd.length} bytes)`);

  // 5. A bad scene pasted: the message the command line prints for the same file.
  const bad = 'name = "bad"\n[[balls]]\nid = "cue"\npos = [0.5, 0.4]\n[[balls]]\nid = "red"\npos = [0.51, 0.4]\n';
  writeFileSync(join(TMP, "pasted.toml"), bad);
  const cliBad = run(["simulate", "pasted.toml"]);
  assert.equal(cliBad.code, 2);
  expected400 = 1;
  await page.fill("#paste", bad);
  await page.click("#import");
  await page.waitForSelector("#status.error");
  const said = await page.textContent("#status");
  assert.equal(said, cliBad.err.trim().replace(/^error: /, ""), "the page shows the command's message");
  assert.equal(expected400, 0, "the bad scene was refused with HTTP 400");
  log("bad scene:", said);

  // 6. Plan on the thesis's example: pick the red, the middle-left pocket and a target on the
  // table. A first plan is cancelled while it runs.
  await page.selectOption("#layout", "chapter7-example");
  await page.click("#load-layout");
  await page.waitForFunction(() => window.lab.position.scene.name === "chapter7-example");
  const redC = await page.evaluate(() => window.lab.ball("red").pos.slice());
  const pocket = await page.$eval('[data-pocket="middle-left"]', (c) => { const r = c.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; });
  await page.click("#pick");
  const r1 = await screen(redC[0], redC[1]);
  await page.mouse.click(r1[0], r1[1]);
  await page.mouse.click(pocket[0], pocket[1]);
  const tgt = await screen(1.2, 0.6);
  await page.mouse.click(tgt[0], tgt[1]);
  const choice = await page.evaluate(() => [document.getElementById("plan-pot").value, document.getElementById("plan-pocket").value, window.lab.plan.target()]);
  assert.equal(choice[0], "red");
  assert.equal(choice[1], "middle-left");
  assert.ok(Math.hypot(choice[2][0] - 1.2, choice[2][1] - 0.6) < 0.005, `target ${choice[2]}`);
  await page.fill("#samples", "1024");
  await page.click("#plan");
  await page.waitForFunction(() => /running: [1-9]/.test(document.getElementById("plan-status").textContent), null, { timeout: 60000 });
  await page.click("#plan-cancel");
  await page.waitForFunction(() => /plan cancelled/.test(document.getElementById("status").textContent), null, { timeout: 60000 });
  log(await page.textContent("#status"));
  await page.fill("#samples", "64");
  await page.fill("#alternatives", "1");
  await page.click("#plan");
  await page.waitForSelector("#plan-summary", { timeout: 300000 });
  const plan = await page.evaluate(() => window.lab.plan.result.plan);
  // The field is read (a layer of the table had its id, and the request sent null).
  assert.equal(plan.alternatives.length, 1, "one alternative asked for");
  assert.ok(plan.best.potted, "the best shot pots the red");
  const spread = await page.$eval("#spread", (c) => [Number(c.getAttribute("cx")), Number(c.getAttribute("cy")), Number(c.getAttribute("r"))]);
  const rb = plan.best.robustness;
  assert.deepEqual(spread, [rb.cue_final_mean[0], rb.cue_final_mean[1], rb.cue_final_spread], "the spread drawn is the planner's");
  log(await page.textContent("#plan-summary"));
  await shot("shotlab-plan.png", "#plan-panel");

  // 7. Play the planned shot: the cue ball ends where the planner said, to the bit.
  await page.click("#play-plan");
  await page.waitForFunction(() => window.lab.shot && window.lab.shot.result.scene === "chapter7-example" && !window.lab.animating);
  await idle();
  const fin = await page.evaluate(() => window.lab.shot.result.final);
  assert.deepEqual(fin.cue.pos.slice(0, 2), plan.best.cue_final, "the planned shot replays");
  assert.equal(fin.red.motion, "pocketed", "the red is potted");
  await shot("shotlab-plan-played.png", "#plan-panel");

  // 8. Play: a new frame, the cue ball in hand placed in the D; break off thin off the red
  // at the pack's lower corner, and the referee judges the stroke.
  await page.click("#new-frame");
  await page.waitForFunction(() => window.lab.position.frame && window.lab.position.frame.ball_in_hand);
  const target = await page.evaluate(() => {
    const reds = window.lab.position.scene.balls.filter((b) => /^red/.test(b.id));
    reds.sort((a, b) => a.pos[1] - b.pos[1] || a.pos[0] - b.pos[0]);
    return reds[0].pos;
  });
  const c0 = await page.evaluate(() => window.lab.ball("cue").pos.slice());
  const thin = Math.atan2(target[1] - 0.04 - c0[1], target[0] - c0[0]);
  await page.fill("#aim", String((thin * 180) / Math.PI));
  await page.dispatchEvent("#aim", "change");
  await page.$eval("#speed", (s) => { s.value = "6"; s.dispatchEvent(new Event("input")); });
  await page.click("#play-stroke");
  await page.waitForSelector("#verdict-line", { timeout: 60000 });
  const verdict = await page.textContent("#verdict-line");
  log("referee:", verdict);
  await idle();
  await page.waitForFunction(() => window.lab.position.frame && !window.lab.animating);
  const fr = await page.evaluate(() => window.lab.position.frame);
  assert.ok(/^(Legal|Foul)/.test(verdict), "a verdict shown");
  assert.ok(fr.to_play === 0 || fr.to_play === 1);
  await shot("shotlab-play.png", "#play-panel");

  // 9. The player's visit on a small open table (3 reds, a low effort, so that it stays quick):
  // its reasoning shows the stroke chosen and the alternatives with the server's numbers, the
  // scoreboard follows the referee's verdicts; then a long visit is cancelled while it thinks.
  const served = new Map();
  page.on("response", async (r) => {
    if (!/\/api\/jobs\/\d+\?since=/.test(r.url())) return;
    try {
      for (const p of (await r.json()).parts || []) served.set(p.number, p);
    } catch {
      // A response the page did not read whole (the test ended): nothing to keep.
    }
  });
  assert.equal(info.player, true, "the server has the player");
  await page.selectOption("#layout", "open-table");
  await page.fill("#reds", "3");
  await page.fill("#seed", "2");
  await page.click("#load-layout");
  await page.waitForFunction(() => window.lab.position.frame && window.lab.position.scene.balls.filter((b) => /^red/.test(b.id)).length === 3);
  await page.selectOption("#replay-speed", "4");
  await page.fill("#player-effort", "400");
  await page.fill("#player-seed", "6");
  await page.click("#player-visit");
  await page.waitForSelector("#player-chosen", { timeout: 120000 });
  // While the visit runs nothing that changes the position or starts other work is offered,
  // and the table takes no drag (loading a layout mid-stroke once froze the page for good).
  const locked = await page.evaluate(() =>
    ["load-layout", "new-frame", "import", "strike", "plan", "play-stroke", "player-visit", "replay"]
      .filter((id) => !document.getElementById(id).disabled)
      .concat(window.lab.table.locked ? [] : ["table"]));
  assert.deepEqual(locked, [], "offered during the visit");
  assert.equal(await page.evaluate(() => document.getElementById("player-cancel").disabled), false);
  const shown = await page.evaluate(() => {
    const head = document.getElementById("player-chosen").textContent;
    const rows = [...document.querySelectorAll("#player-considered tr[data-row]")].map((tr) => ({
      row: tr.dataset.row,
      stroke: tr.cells[1].textContent,
      numbers: Object.fromEntries([...tr.querySelectorAll("td[data-field]")].map((td) => [td.dataset.field, [Number(td.dataset.value), td.textContent]])),
    }));
    return { head, rows };
  });
  const number = Number(/^Stroke (\d+)/.exec(shown.head)[1]);
  for (let i = 0; i < 100 && !served.has(number); i++) await new Promise((r) => setTimeout(r, 50));
  const part = served.get(number);
  assert.ok(part, `the server's stroke ${number} was read`);
  const d = part.decision;
  const considered = [d.plan, ...d.alternatives];
  assert.ok(d.alternatives.length >= 1, "the player weighed at least one alternative");
  assert.equal(shown.rows.length, considered.length, "every stroke considered is listed");
  assert.equal(shown.rows[0].row, "chosen");
  shown.rows.forEach((r, i) => {
    const c = considered[i];
    for (const f of ["pot_probability", "value"]) {
      assert.equal(r.numbers[f][0], c[f], `${r.row} ${i}: ${f} is the server's`);
      assert.equal(r.numbers[f][1], c[f].toFixed(3), `${r.row} ${i}: ${f} shown`);
    }
    const what = c.kind === "safety" ? c.ball : c.pot;
    assert.ok(r.stroke.includes(c.kind) && r.stroke.includes(what), `${r.stroke} names ${c.kind} ${what}`);
  });
  assert.ok(shown.head.includes(d.plan.value.toFixed(3)) && shown.head.includes(d.plan.pot_probability.toFixed(3)), shown.head);
  if (d.cue_ball) assert.ok(shown.head.includes("cue ball in hand placed at"), shown.head);
  log("the player's reasoning:", shown.head, `(${d.alternatives.length} alternatives)`);
  await page.waitForFunction(() => /visit over|visit cancelled|visit failed/.test(document.getElementById("status").textContent), null, { timeout: 300000 });
  await idle();
  const over = await page.textContent("#status");
  assert.ok(/visit over/.test(over), over);
  const freed = await page.evaluate(() =>
    ["load-layout", "strike", "plan", "play-stroke"].filter((id) => document.getElementById(id).disabled));
  assert.deepEqual(freed, [], "still refused after the visit");
  const strokes = Number(/over: (\d+) strokes/.exec(over)[1]);
  await page.waitForFunction((n) => document.querySelectorAll("#strokes li").length >= n, strokes);
  const lines = await page.$$eval("#strokes li", (l) => l.map((x) => x.textContent));
  const mine = lines.slice(-strokes);
  for (let k = 1; k <= strokes; k++) {
    const p = served.get(k);
    assert.ok(p, `stroke ${k} served`);
    const sc = p.referee.scores;
    assert.ok(mine[k - 1].includes(`stroke ${k} (the player)`) && mine[k - 1].endsWith(`Scores ${sc[0]}–${sc[1]}.`), `${mine[k - 1]} vs the referee's ${sc}`);
    assert.ok(mine[k - 1].startsWith(`Player ${p.player}`));
  }
  const sc = served.get(strokes).referee.scores;
  const board = await page.textContent("#scoreboard");
  assert.ok(board.includes(`Player 0: ${sc[0]} · Player 1: ${sc[1]}`) || board.includes(`${sc[0]}–${sc[1]}`), `${board} vs ${sc}`);
  log(`the player's visit: ${strokes} strokes; ${over}; ${board}`);
  await shot("shotlab-player.png", "#play-panel");

  // A frame against the player, who takes the side now to play: its visit starts by itself
  // (at the effort limit, so that it is still thinking when cancelled).
  await page.fill("#player-effort", String(info.limits.play_effort));
  const toPlay = await page.evaluate(() => window.lab.position.frame.to_play);
  await page.selectOption("#player-side", String(toPlay));
  await page.check("#vs-player");
  await page.waitForFunction(() => /running: [1-9]/.test(document.getElementById("player-status").textContent), null, { timeout: 60000 });
  const jobId = await page.evaluate(() => window.lab.player.job);
  await page.click("#player-cancel");
  await page.waitForFunction(() => /visit cancelled/.test(document.getElementById("status").textContent), null, { timeout: 60000 });
  const job = await page.evaluate(async (id) => (await fetch(`/api/jobs/${id}`)).json(), jobId);
  assert.equal(job.state, "cancelled");
  assert.ok(job.shots < info.limits.play_effort, `stopped after ${job.shots} shots`);
  const later = await page.evaluate(async (id) => { await new Promise((r) => setTimeout(r, 500)); return (await fetch(`/api/jobs/${id}`)).json(); }, jobId);
  assert.equal(later.shots, job.shots, "no shot simulated after the cancel");
  log(await page.textContent("#status"));

  // Still a frame against the player, now taking the other side: the person to play gives the
  // table away by hand (the cue ball nudged away from every ball: a foul, no ball hit), and the
  // player's visit starts by itself (a low effort, so that it stays quick).
  await page.fill("#player-effort", "400");
  const person = await page.evaluate(() => window.lab.position.frame.to_play);
  await page.selectOption("#player-side", String(1 - person));
  const away = await page.evaluate(() => {
    const cue = window.lab.ball("cue").pos;
    const others = window.lab.position.scene.balls.filter((b) => b.id !== "cue");
    others.sort((a, b) => Math.hypot(a.pos[0] - cue[0], a.pos[1] - cue[1]) - Math.hypot(b.pos[0] - cue[0], b.pos[1] - cue[1]));
    const n = others[0].pos;
    return (Math.atan2(cue[1] - n[1], cue[0] - n[0]) * 180) / Math.PI;
  });
  await page.fill("#aim", away.toFixed(1));
  await page.dispatchEvent("#aim", "change");
  await page.$eval("#speed", (s) => { s.value = "0.1"; s.dispatchEvent(new Event("input")); });
  const before = await page.$$eval("#strokes li", (l) => l.length);
  await page.click("#play-stroke");
  await page.waitForFunction((n) => document.querySelectorAll("#strokes li").length > n, before, { timeout: 60000 });
  const handLine = await page.$eval("#strokes li:last-child", (x) => x.textContent);
  assert.ok(/Foul/.test(handLine) && !/the player/.test(handLine), `the hand stroke: ${handLine}`);
  await page.waitForFunction((n) => [...document.querySelectorAll("#strokes li")].slice(n + 1).some((x) => /\(the player\)/.test(x.textContent)), before, { timeout: 120000 });
  await page.waitForFunction(() => /visit over|visit cancelled|visit failed/.test(document.getElementById("status").textContent), null, { timeout: 300000 });
  await idle();
  const after = await page.textContent("#status");
  assert.ok(/visit over/.test(after), after);
  log("after a hand stroke that gave the table away:", after);

  assert.deepEqual(problems, [], "no console error, no page error, no request off the local server");
  log("all checks passed");
} finally {
  await browser.close();
  proc.kill("SIGINT");
}
if (problems.length) {
  console.error(problems.join("\n"));
  process.exit(1);
}
