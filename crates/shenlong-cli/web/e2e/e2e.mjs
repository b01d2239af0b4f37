// End-to-end: `shenlong serve` in headless Chromium. Loads the page, types an instruction,
// checks through the API that the scene changed, undoes it, and takes a screenshot.
//
//   SHENLONG_BIN=target/debug/shenlong node e2e.mjs [screenshot.png]
//
// Skips (exit 0, with a message) when Chromium is not installed.
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { chromium } from 'playwright-core';

const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const BIN = process.env.SHENLONG_BIN || new URL('../../../../target/debug/shenlong', import.meta.url).pathname;
const SCREENSHOT = process.argv[2] || '/tmp/shenlong-editor.png';

if (!existsSync(CHROMIUM)) {
  console.log(`e2e: skipped: no Chromium at ${CHROMIUM} (apt-get install chromium)`);
  process.exit(0);
}
if (!existsSync(BIN)) {
  console.error(`e2e: no shenlong binary at ${BIN}: build it first (cargo build)`);
  process.exit(1);
}

// Starts `shenlong serve SCENE` on a free port; resolves to the server and its base URL.
function start(scene) {
  const server = spawn(BIN, ['serve', scene, '--addr', '127.0.0.1:0'], { stdio: ['ignore', 'ignore', 'pipe'] });
  return new Promise((resolve, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error(`the server did not start: ${text}`)), 15000);
    server.stderr.on('data', (chunk) => {
      text += chunk;
      const match = text.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (match) { clearTimeout(timer); resolve({ server, base: match[0] }); }
    });
    server.on('exit', (code) => reject(new Error(`the server exited (${code}): ${text}`)));
  });
}

const { server, base } = await start('example:workshop');
// The shared test data: ../shared/data beside the repository, or $SHENLONG_SHARED_DATA (as the Rust tests).
const SHARED_DATA = process.env.SHENLONG_SHARED_DATA || new URL('../../../../../shared/data', import.meta.url).pathname;
const GLTF = `${SHARED_DATA}/gltf/DepthOfFieldExample.glb`;

let browser;
let failed = 0;
const check = (ok, what) => { if (!ok) { failed++; console.error(`e2e: FAILED: ${what}`); } };
try {
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run', '--disable-quic', '--use-gl=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = await browser.newPage({ viewport: { width: 1280, height: 760 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(base);
  await page.waitForFunction(() => window.shenlong && window.shenlong.ready, null, { timeout: 20000 });
  check(await page.locator('#scene-name').textContent() === 'workshop', 'the page shows the scene name');

  const bottle = async () => {
    const scene = await (await fetch(`${base}api/scene`)).json();
    return scene.scene.objects.find((o) => o.name === 'orange bottle').position;
  };
  check(JSON.stringify(await bottle()) === JSON.stringify([-2, 0, 1.2]), 'the bottle starts on the floor');

  await page.fill('#instruction', 'put the orange bottle on the tool table');
  await page.click('#run');
  await page.waitForFunction(() => document.querySelector('#status').textContent.startsWith('Done'), null, { timeout: 20000 });
  await page.waitForTimeout(900); // the animation
  const report = await page.evaluate(() => window.shenlong.lastReport);
  check(report.query === 'put X1 on X2', `the report's query: ${report.query}`);
  check(report.grounding.length === 2 && report.grounding[0].objects[0] === 'orange bottle', 'the report grounds both phrases');
  check(JSON.stringify(await bottle()) === JSON.stringify([0, 0.9, 0]), 'the API shows the bottle on the table');
  check((await page.locator('#report').textContent()).includes('put X1 on X2'), 'the report panel shows the query');
  check((await page.locator('#report').textContent()).includes('“the tool table” → X2 tool table'), 'the report panel shows the grounding');
  check((await page.locator('#history li').count()) === 1, 'one history entry');
  await page.screenshot({ path: SCREENSHOT });

  await page.click('#undo');
  await page.waitForFunction(() => document.querySelector('#status').textContent === 'Undone', null, { timeout: 10000 });
  check(JSON.stringify(await bottle()) === JSON.stringify([-2, 0, 1.2]), 'undo puts the bottle back');

  await page.fill('#instruction', "move the 'sofaa' left");
  await page.click('#run');
  await page.waitForFunction(() => document.querySelector('#status').className === 'error', null, { timeout: 10000 });
  check((await page.locator('#status').textContent()).includes("unknown object 'sofaa'"), 'errors show in the status line');
  await page.fill('#instruction', 'move the can 30 cm to the left');
  await page.click('#run');
  await page.waitForFunction(() => document.querySelector('#status').textContent.includes('could mean'), null, { timeout: 10000 });
  check((await page.locator('#status').textContent()).includes('paint can and oil can'), 'an ambiguous phrase is refused with its candidates');
  check(errors.length === 0, `no script errors: ${errors.join('; ')}`);

  // A glTF scene is drawn with its meshes (from the shared test data, when present).
  if (existsSync(GLTF)) {
    const gltf = await start(GLTF);
    try {
      const view = await browser.newPage({ viewport: { width: 1280, height: 760 } });
      const gltfErrors = [];
      view.on('pageerror', (e) => gltfErrors.push(e.message));
      await view.goto(gltf.base);
      await view.waitForFunction(() => window.shenlong && window.shenlong.ready, null, { timeout: 30000 });
      const meshes = await view.evaluate(() => window.shenlong.meshes());
      check(meshes > 16, `the glTF meshes are drawn (${meshes} meshes)`);
      await view.fill('#instruction', "move the 'Cube' 0.5 units up");
      await view.click('#run');
      await view.waitForFunction(() => document.querySelector('#status').textContent.startsWith('Done'), null, { timeout: 30000 });
      await view.waitForTimeout(900);
      await view.screenshot({ path: SCREENSHOT.replace(/\.png$/, '-gltf.png') });
      check(gltfErrors.length === 0, `no script errors on the glTF scene: ${gltfErrors.join('; ')}`);
    } finally {
      gltf.server.kill();
    }
  } else {
    console.log(`e2e: the glTF scenario skipped: ${GLTF} not found (the shared test data is absent)`);
  }
} catch (error) {
  failed++;
  console.error(`e2e: FAILED: ${error.message}`);
} finally {
  if (browser) await browser.close();
  server.kill();
}
console.log(`e2e: ${failed === 0 ? 1 : 0} passed, ${failed === 0 ? 0 : 1} failed (screenshot: ${SCREENSHOT})`);
process.exit(failed === 0 ? 0 : 1);
