#!/usr/bin/env node
// The browser edition's speed (scripts/kit bench): per lab, the page's weight (its .js, .wasm and .data), the time from
// navigation to its first frame in headless Chromium, and its frame time against the native binary's on the same
// machine and rasterizer (llvmpipe: through ANGLE in the page, through EGL natively), the lab's first case at its case
// size, both with the reference solution, in interleaved rounds: the ratio's median and its lowest and highest round.
// Usage: bench_web.js SITE_URL BUILD_WEB_DIR BIN_DIR KIT_ROOT   (run under X: ANGLE's GL back end needs a display)
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { chromium } = require(path.join(__dirname, '../web/node_modules/playwright-core'));

const [base, buildWeb, bin, kit] = process.argv.slice(2);
const labs = ['lab01', 'lab02', 'lab03', 'lab04', 'lab05', 'lab06', 'lab07'];
const rounds = 3, frames = 5;
const median = (v) => { const s = [...v].sort((a, b) => a - b); return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2; };
const kib = (bytes) => (bytes / 1024).toFixed(0);

function nativeMs(lab, caseName, size) {
  const out = fs.mkdtempSync('/tmp/gsv-bench-web-');
  execFileSync(path.join(bin, lab + '_solution'), ['render', '--case', caseName, '--size', size, '--profile', 'es',
    '--frames', String(frames), '--warmup', '1', '--out', path.join(out, 'frame.png')], { stdio: 'ignore' });
  const report = JSON.parse(fs.readFileSync(path.join(out, 'frame.json'), 'utf8'));
  fs.rmSync(out, { recursive: true, force: true });
  return report.timing.median_ms;
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--use-gl=angle', '--use-angle=gl', '--ignore-gpu-blocklist'] });
  console.log('lab    weight KiB (js+wasm+data)  first frame ms  page ms/frame  native ms/frame  page/native (lowest, highest round)');
  for (const lab of labs) {
    const dir = path.join(buildWeb, 'site', lab);
    const weight = ['js', 'wasm', 'data'].map((e) => fs.statSync(path.join(dir, lab + '.' + e)).size);
    const cases = JSON.parse(fs.readFileSync(path.join(kit, 'grader/cases', lab + '.json'), 'utf8'));
    const caseName = cases.cases[0].name, size = cases.size;
    const page = await browser.newPage();
    await page.goto(base + '/lecturer/' + lab + '/index.html?case=' + caseName);
    await page.waitForFunction(() => window.gsvPage && (window.gsvPage.frames > 0 || window.gsvPage.failed), null, { timeout: 120000 });
    const first = await page.evaluate(() => window.gsvPage.firstFrameMs);
    const ratios = [], pageTimes = [], nativeTimes = [];
    for (let r = 0; r < rounds; r++) {
      // Each page frame redraws the case from its settings, as a headless render's frames do (lab 05 recomputes its run).
      const inPage = await page.evaluate((n) => {
        Module.applyCase(new URLSearchParams(location.search).get('case'));
        Module.draw();
        const t = [];
        for (let i = 0; i < n; i++) { Module.applyCase(new URLSearchParams(location.search).get('case')); t.push(Module.draw()); }
        t.sort((a, b) => a - b);
        return t[(t.length - 1) >> 1];
      }, frames);
      const native = nativeMs(lab, caseName, size);
      pageTimes.push(inPage);
      nativeTimes.push(native);
      ratios.push(inPage / native);
    }
    await page.close();
    console.log(lab.padEnd(6) + ' ' + (kib(weight[0]) + '+' + kib(weight[1]) + '+' + kib(weight[2])).padEnd(26) +
                String(Math.round(first)).padStart(14) + median(pageTimes).toFixed(1).padStart(15) +
                median(nativeTimes).toFixed(1).padStart(17) + '   ' + median(ratios).toFixed(2) + ' (' +
                Math.min(...ratios).toFixed(2) + ', ' + Math.max(...ratios).toFixed(2) + ')');
  }
  await browser.close();
})();
