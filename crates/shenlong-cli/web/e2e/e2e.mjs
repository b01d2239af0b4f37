// End-to-end: `shenlong serve` in headless Chromium.
//
// The workshop: loads the page, types an instruction, checks through the API that the
// scene changed, undoes it, and takes a screenshot.
// The kitchen (kitchen.json beside this script: four identical chairs, and an object
// named `<img src=x onerror=alert(1)>`): an edit made through the API before the page
// opens is shown on load; the outliner, its filter, hover and labels in both the list and
// the view; an ambiguous instruction offered as a choice, a click on a candidate, the edit
// applied with its phrases marked and the ghost of where the chair was; Enter, Shift+Enter,
// Ctrl+Z and Ctrl+Shift+Z; the hostile name shown as text, never as markup. On every page:
// no script error, and no Content-Security-Policy violation reported on the console.
//
//   SHENLONG_BIN=target/debug/shenlong node e2e.mjs [screenshot.png [images-folder]]
//
// The kitchen's screenshots (the choice, the ghost) go to images-folder as
// editor-choice.png and editor-ghost.png, or beside screenshot.png (NAME-choice.png,
// NAME-ghost.png) when no folder is given.
//
// Skips (exit 0, with a message) when Chromium is not installed.
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const BIN = process.env.SHENLONG_BIN || new URL('../../../../target/debug/shenlong', import.meta.url).pathname;
const SCREENSHOT = process.argv[2] || '/tmp/shenlong-editor.png';
const IMAGES = process.argv[3];
const CHOICE_PNG = IMAGES ? join(IMAGES, 'editor-choice.png') : SCREENSHOT.replace(/(\.png)?$/, '-choice.png');
const GHOST_PNG = IMAGES ? join(IMAGES, 'editor-ghost.png') : SCREENSHOT.replace(/(\.png)?$/, '-ghost.png');
const KITCHEN = new URL('./kitchen.json', import.meta.url).pathname;
const HOSTILE = '<img src=x onerror=alert(1)>';

if (!existsSync(CHROMIUM)) {
  console.log(`e2e: skipped: no Chromium at ${CHROMIUM} (apt-get install chromium)`);
  process.exit(0);
}
if (!existsSync(BIN)) {
  console.error(`e2e: no shenlong binary at ${BIN}: build it first (cargo build)`);
  process.exit(1);
}
if (IMAGES) mkdirSync(IMAGES, { recursive: true });

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

// The API as a client: status and JSON.
async function request(base, path, body) {
  const response = await fetch(`${base}${path}`, body === undefined ? {} : {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
  });
  return { status: response.status, json: await response.json() };
}

const servers = [];
const { server, base } = await start('example:workshop');
servers.push(server);
// The shared test data: ../shared/data beside the repository, or $SHENLONG_SHARED_DATA (as the Rust tests).
const SHARED_DATA = process.env.SHENLONG_SHARED_DATA || new URL('../../../../../shared/data', import.meta.url).pathname;
const GLTF = `${SHARED_DATA}/gltf/DepthOfFieldExample.glb`;

let browser;
let failed = 0;
let checks = 0;
const check = (ok, what) => { checks++; if (!ok) { failed++; console.error(`e2e: FAILED: ${what}`); } };
const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
const near = (a, b) => a.length === b.length && a.every((x, i) => Math.abs(x - b[i]) < 1e-9);

// A page on `url` with its script errors and dialogs recorded.
async function open(url) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 760 } });
  const errors = [];
  const dialogs = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // A Content-Security-Policy violation is reported on the console.
  page.on('console', (m) => { if (/Content Security Policy/i.test(m.text())) errors.push(m.text()); });
  page.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss().catch(() => {}); });
  await page.goto(url);
  await page.waitForFunction(() => window.shenlong && window.shenlong.ready, null, { timeout: 20000 });
  return { page, errors, dialogs };
}

async function workshop() {
  const { page, errors } = await open(base);
  check(await page.locator('#scene-name').textContent() === 'workshop', 'the page shows the scene name');

  const bottle = async () => {
    const scene = (await request(base, 'api/scene')).json;
    return scene.scene.objects.find((o) => o.name === 'orange bottle').position;
  };
  check(same(await bottle(), [-2, 0, 1.2]), 'the bottle starts on the floor');
  check(await page.locator('#report').textContent() === 'No edit yet.', 'no edit yet on a fresh server');

  await page.fill('#instruction', 'put the orange bottle on the tool table');
  await page.click('#run');
  await page.waitForFunction(() => document.querySelector('#status').textContent.startsWith('Done'), null, { timeout: 20000 });
  await page.waitForTimeout(900); // the animation
  const report = await page.evaluate(() => window.shenlong.lastReport);
  check(report.query === 'put X1 on X2', `the report's query: ${report.query}`);
  check(report.grounding.length === 2 && report.grounding[0].objects[0] === 'orange bottle', 'the report grounds both phrases');
  check(same(await bottle(), [0, 0.9, 0]), 'the API shows the bottle on the table');
  check((await page.locator('#report').textContent()).includes('put X1 on X2'), 'the report panel shows the query');
  check((await page.locator('#report').textContent()).includes('“the tool table” → X2 tool table'), 'the report panel shows the grounding');
  check((await page.locator('#history li').count()) === 1, 'one history entry');
  await page.screenshot({ path: SCREENSHOT });

  await page.click('#undo');
  await page.waitForFunction(() => document.querySelector('#status').textContent === 'Undone', null, { timeout: 10000 });
  check(same(await bottle(), [-2, 0, 1.2]), 'undo puts the bottle back');

  await page.fill('#instruction', "move the 'sofaa' left");
  await page.click('#run');
  await page.waitForFunction(() => document.querySelector('#status').className === 'error', null, { timeout: 10000 });
  check((await page.locator('#status').textContent()).includes("unknown object 'sofaa'"), 'errors show in the status line');
  check(await page.locator('#choice').isHidden(), 'a refusal without candidates offers no choice');
  await page.fill('#instruction', 'move the can 30 cm to the left');
  await page.click('#run');
  await page.waitForFunction(() => document.querySelector('#status').textContent.includes('could mean'), null, { timeout: 10000 });
  check((await page.locator('#status').textContent()).includes('paint can and oil can'), 'an ambiguous phrase is refused with its candidates');
  check(same(await page.locator('#choices button').allTextContents(), ['paint can', 'oil can']), 'the candidates are offered as buttons');
  check(errors.length === 0, `no script errors or policy violations: ${errors.join('; ')}`);
  await page.close();
}

async function kitchen() {
  const kitchenServer = await start(KITCHEN);
  servers.push(kitchenServer.server);
  const at = kitchenServer.base;
  const position = async (name) => (await request(at, 'api/scene')).json.scene.objects.find((o) => o.name === name).position;

  // An edit through the API before the page opens.
  const before = await request(at, 'api/edit', { instruction: 'move the fruit bowl 10 cm to the left' });
  check(before.status === 200, `an edit through the API: ${before.status}`);
  check(same(before.json.moved, [{ object: 'fruit bowl', how: 'moved', before: { position: [0.2, 0.75, 0.1], rotation: [0, 0, 0, 1], scale: 1 }, after: { position: [0.1, 0.75, 0.1], rotation: [0, 0, 0, 1], scale: 1 } }]),
    `the edit's answer says what moved and from where: ${JSON.stringify(before.json.moved)}`);

  const { page, errors, dialogs } = await open(at);
  const status = () => page.locator('#status').textContent();
  const waitStatus = (test, timeout = 20000) => page.waitForFunction(test, null, { timeout });
  const row = (name) => page.locator('#object-list').getByRole('button', { name, exact: true });
  const shenlong = (f, ...args) => page.evaluate(([name, rest]) => window.shenlong[name](...rest), [f, args]);

  // 4. The placeholder is made from this scene's objects; the last edit and the history on load.
  const example = (await request(at, 'api/scene')).json.example;
  const placeholder = await page.locator('#instruction').getAttribute('placeholder');
  check(placeholder === example && /kettle|dining table|fruit bowl|chair|fridge|counter/.test(placeholder) && !placeholder.includes('orange bottle'),
    `the placeholder is made from the kitchen's objects: ${placeholder}`);
  check((await page.locator('#understood').textContent()) === 'Understood: move the fruit bowlX1 10 cm to the left',
    `the last edit, made before the page opened, is shown: ${await page.locator('#understood').textContent()}`);
  check((await page.locator('#history li').count()) === 1, 'the history is shown on load');
  check(same(await shenlong('ghosts'), [{ object: 'fruit bowl', position: [0.2, 0.75, 0.1] }]), 'the last edit\'s ghost is shown on load');

  // 1. The outliner: every object, its names as text; filter; hover in both; click inserts.
  const rows = await page.locator('#object-list button').allTextContents();
  check(rows.length === 10 && rows.includes(HOSTILE) && rows.includes('chair 3'), `the outliner lists every object: ${rows.join(' | ')}`);
  check(await page.evaluate(() => document.querySelectorAll('img').length) === 0, 'a name is never markup: no <img> on the page');
  await page.fill('#filter', 'chair');
  check((await page.locator('#object-list li:not([hidden])').count()) === 4, 'typing "chair" leaves the four chairs');
  await page.fill('#filter', 'CHAIR 3');
  check(same(await page.locator('#object-list li:not([hidden])').allTextContents(), ['chair 3']), 'the filter ignores case');
  await page.fill('#filter', '');
  check((await page.locator('#object-list li:not([hidden])').count()) === 10, 'an empty filter shows every object');
  await row('chair 2').hover();
  check(same(await shenlong('highlighted'), ['chair 2']), 'hovering a row highlights its object in the view');
  check((await shenlong('labels')).includes('chair 2'), 'and shows its name in the view');
  const chair4 = await shenlong('pointAt', 'chair 4', 0.9);
  await page.mouse.move(chair4.x, chair4.y);
  check(same(await shenlong('highlighted'), ['chair 4']), `hovering an object in the view highlights it: ${await shenlong('highlighted')}`);
  check(await row('chair 4').evaluate((b) => b.classList.contains('hover')), 'and its row in the list');
  check(same(await page.locator('#labels .label.hover').allTextContents(), ['chair 4']), 'and labels it in the view');
  await page.fill('#instruction', 'put ');
  await page.mouse.click(chair4.x, chair4.y);
  check(await page.inputValue('#instruction') === 'put ', `a click selects, it does not type: ${await page.inputValue('#instruction')}`);
  check(await row('chair 4').evaluate((b) => b.classList.contains('selected')), 'a click in the view selects the object');
  await row('fridge').click({ modifiers: ['Shift'] });
  check((await page.locator('#selection').textContent()).includes('chair 4, fridge'), `Shift+click adds to the selection: ${await page.locator('#selection').textContent()}`);
  check(same((await shenlong('labels')).sort(), ['chair 4', 'fridge', 'fruit bowl']), `selected objects are labelled: ${await shenlong('labels')}`);
  await row('fridge').dblclick();
  check((await page.inputValue('#instruction')).includes("'fridge'"), `a double-click inserts the name: ${await page.inputValue('#instruction')}`);
  await page.mouse.move(5, 5);
  await page.keyboard.press('Escape');
  check(same(await shenlong('labels'), ['fruit bowl']), `Esc clears the selection: ${await shenlong('labels')}`);
  check((await page.locator('#selection').textContent()) === '', 'and says so');

  // 2. Ambiguity as a choice, run by Enter.
  const refused = await request(at, 'api/edit', { instruction: 'move the chair 50 cm to the left' });
  check(refused.status === 422 && refused.json.ambiguity && refused.json.ambiguity.phrase === 'the chair'
    && same(refused.json.ambiguity.objects, ['chair 1', 'chair 2', 'chair 3', 'chair 4']), `the API's choice: ${JSON.stringify(refused.json)}`);
  await page.fill('#instruction', 'move the chair 50 cm to the left');
  await page.press('#instruction', 'Enter');
  await waitStatus(() => document.querySelector('#status').textContent.includes('could mean'));
  check(await page.locator('#choice').isVisible(), 'the choice is shown');
  check(same(await page.locator('#choices button').allTextContents(), ['chair 1', 'chair 2', 'chair 3', 'chair 4']), 'the four chairs are offered');
  check((await page.locator('#choice-text').textContent()).includes('“the chair”'), 'the choice names the phrase');
  check(same((await shenlong('labels')).sort(), ['chair 1', 'chair 2', 'chair 3', 'chair 4', 'fruit bowl']), `the candidates are named in the view: ${await shenlong('labels')}`);
  check((await page.locator('#object-list button.candidate').count()) === 4, 'and marked in the list');
  await page.hover('#choices button:text-is("chair 3")');
  check(same(await shenlong('highlighted'), ['chair 3']), 'hovering a candidate highlights it');
  await page.waitForTimeout(200);
  await page.screenshot({ path: CHOICE_PNG });

  // A click on a candidate runs the instruction with it named.
  check(same(await position('chair 3'), [-0.45, 0, 0.75]), 'chair 3 starts at the table');
  await page.click('#choices button:text-is("chair 3")');
  await waitStatus(() => document.querySelector('#status').textContent.startsWith('Done'));
  check(await page.inputValue('#instruction') === "move 'chair 3' 50 cm to the left", `the instruction names the chair: ${await page.inputValue('#instruction')}`);
  check(near(await position('chair 3'), [-0.95, 0, 0.75]), `chair 3 moved 50 cm to the left: ${await position('chair 3')}`);
  check(near(await position('chair 1'), [-0.45, 0, -0.75]), 'the other chairs stay');
  check(await page.locator('#choice').isHidden(), 'the choice is gone after the edit');

  // 3. What was understood, and the ghost.
  check((await page.locator('#understood').textContent()) === "Understood: move 'chair 3'X1 50 cm to the left", `the phrase is marked: ${await page.locator('#understood').textContent()}`);
  check(same(await shenlong('ghosts'), [{ object: 'chair 3', position: [-0.45, 0, 0.75] }]), `the ghost shows where chair 3 was: ${JSON.stringify(await shenlong('ghosts'))}`);
  check((await page.locator('#labels .label.ghost:visible').count()) === 1, 'the ghost is labelled in the view');
  await page.hover('#understood mark');
  check(same(await shenlong('highlighted'), ['chair 3']), 'hovering the marked phrase highlights its object');
  await page.mouse.move(5, 5);
  await page.waitForTimeout(800); // the animation
  await page.screenshot({ path: GHOST_PNG });

  // 5. Keyboard: Shift+Enter is a new line; Ctrl+Z in the box is the box's; outside it undoes.
  const historyLength = (await request(at, 'api/history')).json.history.length;
  await page.fill('#instruction', 'move the kettle');
  await page.press('#instruction', 'Shift+Enter');
  check(await page.inputValue('#instruction') === 'move the kettle\n', 'Shift+Enter makes a new line');
  await page.press('#instruction', 'Control+z');
  await page.waitForTimeout(300);
  check((await request(at, 'api/history')).json.history.length === historyLength && near(await position('chair 3'), [-0.95, 0, 0.75]),
    'neither Shift+Enter nor Ctrl+Z in the instruction box runs or undoes anything');
  await page.evaluate(() => document.activeElement.blur());
  await page.keyboard.press('Control+z');
  await waitStatus(() => document.querySelector('#status').textContent === 'Undone', 10000);
  check(near(await position('chair 3'), [-0.45, 0, 0.75]), 'Ctrl+Z undoes: chair 3 is back');
  check(same(await shenlong('ghosts'), []), 'the ghost goes with the undo');
  check((await page.locator('#labels .label.ghost').count()) === 0, 'and its label');
  await page.keyboard.press('Control+Shift+Z');
  await waitStatus(() => document.querySelector('#status').textContent === 'Redone', 10000);
  check(near(await position('chair 3'), [-0.95, 0, 0.75]), 'Ctrl+Shift+Z redoes');

  // The conversation: the selection is "it"; a follow-up leans on the last edit.
  const chair2 = await position('chair 2');
  await row('chair 2').click();
  await page.fill('#instruction', 'move it 20 cm to the left');
  await page.keyboard.press('Enter');
  await waitStatus(() => document.querySelector('#status').textContent.startsWith('Done'));
  check(near(await position('chair 2'), [chair2[0] - 0.2, chair2[1], chair2[2]]), `"it" is the selected chair 2: ${await position('chair 2')}`);
  await page.fill('#instruction', 'a bit more');
  await page.keyboard.press('Enter');
  await waitStatus(() => document.querySelector('#status').textContent.startsWith('Done'));
  check(near(await position('chair 2'), [chair2[0] - 0.3, chair2[1], chair2[2]]), `"a bit more" moves it 10 cm further: ${await position('chair 2')}`);
  await page.fill('#instruction', 'put it back');
  await page.keyboard.press('Enter');
  await waitStatus(() => document.querySelector('#status').textContent.startsWith('Done'));
  check(near(await position('chair 2'), [chair2[0] - 0.2, chair2[1], chair2[2]]), `"put it back" undoes the last move of it: ${await position('chair 2')}`);
  const turns = await page.locator('#conversation li').allTextContents();
  check(turns.length >= 3 && turns[turns.length - 1].startsWith('put it back'), `the panel shows the conversation: ${turns.join(' | ')}`);

  // A hostile name: inserted, edited, reported and labelled as text.
  await page.fill('#instruction', 'move ');
  await row(HOSTILE).dblclick();
  await page.keyboard.type(' 30 cm to the left');
  check(await page.inputValue('#instruction') === `move '${HOSTILE}' 30 cm to the left`, 'a double-click inserts the hostile name quoted');
  await page.keyboard.press('Enter');
  await waitStatus(() => document.querySelector('#status').textContent.startsWith('Done'));
  check((await page.locator('#understood').textContent()) === `Understood: move '${HOSTILE}'X1 30 cm to the left`, 'the hostile name is shown as text in the report');
  check((await page.locator('#labels .label').allTextContents()).includes(HOSTILE), 'and in the view');
  check(near(await position(HOSTILE), [1.6, 0, 1.4]), 'the object with the hostile name moved');
  check(await page.evaluate(() => document.querySelectorAll('img, [onerror]').length) === 0, 'no markup from a name reached the page');
  check(dialogs.length === 0, `no dialog was opened: ${dialogs.join('; ')}`);
  check(errors.length === 0, `no script errors or policy violations on the kitchen: ${errors.join('; ')}`);
  await page.close();
}

try {
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run', '--disable-quic', '--use-gl=swiftshader', '--enable-unsafe-swiftshader'],
  });
  await workshop();
  await kitchen();

  // A glTF scene is drawn with its meshes (from the shared test data, when present).
  if (existsSync(GLTF)) {
    const gltf = await start(GLTF);
    servers.push(gltf.server);
    const { page: view, errors: gltfErrors } = await open(gltf.base);
    const meshes = await view.evaluate(() => window.shenlong.meshes());
    check(meshes > 16, `the glTF meshes are drawn (${meshes} meshes)`);
    await view.fill('#instruction', "move the 'Cube' 0.5 units up");
    await view.click('#run');
    await view.waitForFunction(() => document.querySelector('#status').textContent.startsWith('Done'), null, { timeout: 30000 });
    await view.waitForTimeout(900);
    await view.screenshot({ path: SCREENSHOT.replace(/\.png$/, '-gltf.png') });
    check(gltfErrors.length === 0, `no script errors or policy violations on the glTF scene: ${gltfErrors.join('; ')}`);
  } else {
    console.log(`e2e: the glTF scenario skipped: ${GLTF} not found (the shared test data is absent)`);
  }
} catch (error) {
  failed++;
  console.error(`e2e: FAILED: ${error.message}`);
} finally {
  if (browser) await browser.close();
  for (const s of servers) s.kill();
}
console.log(`e2e: ${failed === 0 ? 1 : 0} passed, ${failed === 0 ? 0 : 1} failed; ${checks} checks, ${failed} failed `
  + `(screenshots: ${SCREENSHOT}, ${CHOICE_PNG}, ${GHOST_PNG})`);
process.exit(failed === 0 ? 0 : 1);
