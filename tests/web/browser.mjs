// The browser test: the site in Debian's headless Chromium, driven by Playwright's core, served from 127.0.0.1.
//
//   node browser.mjs --site build/web/site --scenes scenes --out FOLDER
//
// It opens the start page, then lesson 1 by its link; steps with the keys; types a wrong answer, then the right
// one, and reads the verdicts; reloads and finds the progress kept; downloads the progress and imports it back, and
// downloads lesson 1's worksheet; opens a case through the file input and downloads its trace, table and a
// screenshot; takes a picture at 1024x768, 1280x800 and 1920x1080 and holds each to the app's own layout check; and
// takes every lesson to its end at 1280x800 and 1024x768 (skipping each question with its Skip button). It waits on the site's test
// hook (window.impulseLab.state()), never on a clock, and fails on any error the page logs.

import { chromium } from 'playwright-core';
import { createServer } from 'node:http';
import { mkdirSync, readFileSync, writeFileSync, existsSync } from 'node:fs';
import { extname, join, normalize } from 'node:path';

function option(name) {
  const i = process.argv.indexOf(name);
  if (i < 0 || i + 1 >= process.argv.length) {
    console.error(`browser.mjs: ${name} is missing`);
    process.exit(2);
  }
  return process.argv[i + 1];
}
const site = option('--site');
const scenes = option('--scenes');
const out = option('--out');
mkdirSync(out, { recursive: true });

// A static server for the site folder, as a teacher's would be (python3 -m http.server does the same).
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.data': 'application/octet-stream' };
const server = createServer((request, response) => {
  const path = normalize(decodeURIComponent(new URL(request.url, 'http://x').pathname)).replace(/^\/+/, '');
  const file = join(site, path === '' ? 'index.html' : path);
  if (!file.startsWith(site) || !existsSync(file)) {
    response.writeHead(404).end();
    return;
  }
  response.writeHead(200, { 'Content-Type': types[extname(file)] ?? 'application/octet-stream' });
  response.end(readFileSync(file));
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const origin = `http://127.0.0.1:${server.address().port}`;

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
         '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
});
const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
const page = await context.newPage();
const pageErrors = [];
page.on('console', (message) => { if (message.type() === 'error') pageErrors.push(message.text()); });
page.on('pageerror', (error) => pageErrors.push(String(error)));

let passed = 0, failed = 0;
function check(condition, what) {
  if (condition) {
    ++passed;
  } else {
    ++failed;
    console.log(`FAILED: ${what}`);
  }
}
const state = () => page.evaluate(() => window.impulseLab.state());
// Waits until the site's state satisfies `test(state, arg)` (run in the page, so it sees only its arguments); 60 s at
// most.
async function until(test, what, arg = null) {
  try {
    await page.waitForFunction(({ source, arg }) => {
      try {
        return (0, eval)(`(${source})`)(window.impulseLab.state(), arg);
      } catch (e) {
        return false;
      }
    }, { source: test.toString(), arg }, { timeout: 60000, polling: 'raf' });
    return true;
  } catch (e) {
    check(false, `${what} (last state: ${JSON.stringify(await state().catch(() => null))?.slice(0, 600)})`);
    return false;
  }
}
// Clicks one of the site's controls (the start page's buttons, the inspector's tabs and export buttons) where the
// last frame laid it out, once the page has settled: a message or a question appears in the state before the frames
// that lay it out, and a click where a control was a frame before can miss it.
async function clickControl(what) {
  await until((t, a) => t.idle && (t.controls ?? []).some((i) => i.what === a), `${what} is laid out`, what);
  const s = await state();
  const item = (s.controls ?? []).find((i) => i.what === what);
  if (!item) return false;
  const [x0, y0, x1, y1] = item.box;
  await page.mouse.click((x0 + x1) / 2, (y0 + y1) / 2);
  return true;
}
// Clicks a control and returns the download it starts: its name and its bytes.
async function download(what) {
  if (!await until((t, a) => t.idle && (t.controls ?? []).some((i) => i.what === a), `${what} is laid out`, what)) {
    return { name: '', bytes: Buffer.alloc(0) };
  }
  try {
    const [file] = await Promise.all([page.waitForEvent('download', { timeout: 60000 }), clickControl(what)]);
    return { name: file.suggestedFilename(), bytes: readFileSync(await file.path()) };
  } catch (e) {
    check(false, `${what} starts a download (${e.message.split('\n')[0]})`);
    return { name: '', bytes: Buffer.alloc(0) };
  }
}
async function clickItem(what) {
  await until((t, a) => t.idle && (t.items ?? []).some((i) => i.what === a), `${what} is laid out`, what);
  const s = await state();
  const item = (s.items ?? []).find((i) => i.what === what);
  if (!item) return false;
  const [x0, y0, x1, y1] = item.box;
  await page.mouse.click((x0 + x1) / 2, (y0 + y1) / 2);
  return true;
}

try {
  // The start page, then lesson 1 by its link; the first load of lesson 1 is timed.
  const started = Date.now();
  await page.goto(`${origin}/index.html#lesson=1`);
  await until((s) => s.screen === 'lesson' && s.lesson.step >= 1 && s.frames > 2, 'lesson 1 opens from its link');
  console.log(`browser: lesson 1 interactive ${Date.now() - started} ms after the page was asked for`);
  await page.evaluate(() => { location.hash = ''; });
  await until((s) => s.screen === 'start' && s.lessons.length === 14, 'the start page lists the fourteen lessons');
  await page.evaluate(() => { location.hash = '#lesson=1'; });
  await until((s) => s.screen === 'lesson' && s.lesson.number === 1, 'lesson 1 opens again');

  // Step to the first question with the → key.
  let s = await state();
  check(s.lesson.step === 1, 'lesson 1 starts at its first step');
  await page.keyboard.press('ArrowRight');
  await until((t) => t.lesson.step === 2, '→ moves to step 2');
  s = await state();
  check(s.lesson.question && s.lesson.question.kind === 'predict' && s.lesson.question.state === 'open',
        'step 2 asks to predict a value');

  // A wrong answer, then the right one. The ball has m = 2 kg and the normal runs through its centre, so a unit
  // impulse along the normal changes the separating velocity by d = 1/m = 0.5 m/s and turns nothing (14.1-14.3).
  await page.keyboard.type('3');
  await page.keyboard.press('Enter');
  await until((t) => t.lesson.question.feedback !== '' && t.lesson.question.state === 'open',
              'a wrong answer gets a verdict and leaves the question open');
  s = await state();
  check(!s.lesson.question.feedback.startsWith('right'), `the verdict on 3 is not "right": ${s.lesson.question.feedback}`);
  await page.keyboard.press('Control+A');
  await page.keyboard.type('0.5');
  await page.keyboard.press('Enter');
  await until((t) => t.lesson.question.state === 'answered', '0.5 answers the question');
  s = await state();
  check(s.lesson.question.feedback.startsWith('right'), `the verdict on 0.5 is "right": ${s.lesson.question.feedback}`);

  // The progress survives a reload.
  await page.reload();
  await until((t) => t.screen === 'lesson' && t.lesson.number === 1, 'lesson 1 opens again after a reload');
  s = await state();
  check(s.lesson.step === 2 && s.lesson.question.state === 'answered',
        `after a reload the lesson is back at step 2, answered (step ${s.lesson.step}, ${s.lesson.question?.state})`);
  await page.evaluate(() => { location.hash = ''; });
  await until((t) => t.screen === 'start', 'Back to the start page');
  s = await state();
  check(s.lessons[0].progress.includes('right'), `the start page shows lesson 1's progress: ${s.lessons[0].progress}`);

  // The downloads of the start page: the progress, as the desktop's progress.json, and a lesson's worksheet; the
  // progress then imported back through the page's file picker.
  let file = await download('button Export progress.json');
  let progress = null;
  try { progress = JSON.parse(file.bytes.toString('utf8')); } catch (e) { /* checked below */ }
  check(file.name === 'progress.json' && progress !== null && JSON.stringify(progress).includes('01-'),
        `Export progress.json downloads progress.json with lesson 1 in it (${file.name}, ${file.bytes.length} bytes)`);
  const progressCopy = join(out, 'progress-downloaded.json');
  writeFileSync(progressCopy, file.bytes);
  const [chooser] = await Promise.all([page.waitForEvent('filechooser'), clickControl('button Import progress.json')]);
  await chooser.setFiles(progressCopy);
  await until((t) => t.screen === 'start' && t.message.startsWith('progress imported'), 'the progress imports back');
  s = await state();
  check(s.lessons[0].progress.includes('right'), `lesson 1's progress after the import: ${s.lessons[0].progress}`);
  file = await download('button Worksheet 1');
  const sheet = file.bytes.toString('utf8').split('\n');
  check(/^01-.*-worksheet\.csv$/.test(file.name) && sheet[0] === 'kind,path,step,quantity,value,unit,formula,equation,meaning' &&
        sheet.length > 10, `Worksheet 1 downloads lesson 1's worksheet as CSV (${file.name}: ${sheet[0]}, ${sheet.length} lines)`);

  // A case through the page's file picker.
  const [picker] = await Promise.all([page.waitForEvent('filechooser'), clickControl('button Open a file')]);
  await picker.setFiles(join(scenes, 'cases', 'ruler.json'));
  await until((t) => t.screen === 'inspector' && t.file.endsWith('ruler.json'), 'a case opens from the file picker');

  // The inspector's exports (its Export panel), each a download: the trace as JSON, the table as CSV, a screenshot
  // as PNG.
  file = await download('button Export trace');
  let trace = null;
  try { trace = JSON.parse(file.bytes.toString('utf8')); } catch (e) { /* checked below */ }
  check(file.name === 'trace.json' && trace !== null && Array.isArray(trace.frames) && trace.frames.length > 0,
        `Export trace downloads the trace as JSON (${file.name}, ${file.bytes.length} bytes)`);
  file = await download('button Export table');
  const table = file.bytes.toString('utf8').split('\n');
  check(file.name === 'table.csv' && table.length > 3 && table[0].includes(','),
        `Export table downloads the table as CSV (${file.name}: ${table[0]})`);
  file = await download('button Screenshot');
  s = await state();
  const png = file.bytes;
  const pngWidth = png.length > 24 ? png.readUInt32BE(16) : 0, pngHeight = png.length > 24 ? png.readUInt32BE(20) : 0;
  check(file.name === 'screenshot.png' && png.subarray(1, 4).toString('latin1') === 'PNG' &&
        pngWidth === Math.round(s.width * s.pixel_ratio) && pngHeight === Math.round(s.height * s.pixel_ratio),
        `Screenshot downloads the canvas as PNG (${file.name}, ${pngWidth}x${pngHeight} for ${s.width}x${s.height})`);

  // Pictures at three sizes, each held to the app's own layout check: the lesson panel's items as laid out in this
  // frame lie inside the window, and the check of every step of the lesson at this size finds nothing.
  await page.evaluate(() => { location.hash = '#lesson=1'; });
  await until((t) => t.screen === 'lesson', 'lesson 1 opens for the pictures');
  for (const [width, height] of [[1024, 768], [1280, 800], [1920, 1080]]) {
    await page.setViewportSize({ width, height });
    await until((t, a) => t.width === a[0] && t.height === a[1] && t.items.length > 0 && t.idle,
                `the page follows the window to ${width}x${height}`, [width, height]);
    await page.screenshot({ path: join(out, `lesson-01-${width}x${height}.png`) });
    s = await state();
    const outside = s.items.filter((i) => i.box[0] < -1 || i.box[1] < -1 || i.box[2] > width + 1 || i.box[3] > height + 1);
    check(outside.length === 0, `at ${width}x${height} every item of the lesson panel is inside the window: ` +
                                 outside.map((i) => i.what).join(', '));
    const report = await page.evaluate(([w, h]) => window.impulseLab.layoutCheck(w, h), [width, height]);
    const problems = report.split('\n').slice(1).filter((line) => line !== '');
    check(problems.length === 0, `the layout check at ${width}x${height}: ${report}`);
  }
  // In a lesson the exports are a tab; with questions still open the table comes as shown, their values hidden.
  await until((t) => (t.controls ?? []).some((i) => i.what === 'tab Export'), 'the lesson lays out its Export tab');
  await clickControl('tab Export');
  file = await download('button Export table');
  check(file.name === 'table.csv' && file.bytes.toString('utf8').split('\n').length > 3,
        `in a lesson, Export table downloads the table as shown (${file.name}, ${file.bytes.length} bytes)`);

  // Every lesson to its end at two sizes: each question skipped with its button, every step reached with →.
  for (const [width, height] of [[1280, 800], [1024, 768]]) {
    await page.setViewportSize({ width, height });
    for (let number = 1; number <= 13; ++number) {
      await page.evaluate((n) => { location.hash = `#lesson=${n}`; }, number);
      if (!await until((t, a) => t.screen === 'lesson' && t.lesson.number === a[0] && t.width === a[1],
                       `lesson ${number} opens at ${width}x${height}`, [number, width])) continue;
      const steps = (await state()).lesson.steps;
      for (let guard = 0; guard < 3 * steps; ++guard) {
        s = await state();
        if (s.lesson.question && s.lesson.question.state === 'open') {
          // clickItem waits for the panel to settle: in the frames after → its question's height is known a frame late.
          await clickItem('button Skip');
          await until((t) => t.lesson.question.state !== 'open', `Skip gives lesson ${number}'s step ${s.lesson.step} up`);
          continue;
        }
        if (s.lesson.step === steps) break;
        await page.keyboard.press('ArrowRight');
        await until((t, a) => t.lesson.step === a, `→ in lesson ${number} at step ${s.lesson.step}`, s.lesson.step + 1);
      }
      s = await state();
      check(s.lesson.step === steps && (!s.lesson.question || s.lesson.question.state !== 'open'),
            `lesson ${number} taken to its end at ${width}x${height} (step ${s.lesson.step} of ${steps})`);
    }
  }
  check(pageErrors.length === 0, `the page logged no error: ${pageErrors.join(' | ')}`);
} finally {
  await browser.close();
  server.close();
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
