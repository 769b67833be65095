// Browser test of the page: Debian's chromium, driven by playwright-core, against `make serve`'s
// server (started here). Loads the page, sets IMAGE (a gray PNG), runs METHOD at DENSITY %, reads
// the PSNR and vertex count the page shows and the downloaded model, and prints them as
// "page: vertices N psnr P model-bytes B model-sha256 H ms T" for tests/web_test.sh to compare
// with the native erd. Takes a screenshot (SHOT).
//   node web/test/page_test.mjs IMAGE METHOD DENSITY SHOT MODEL_COPY [PORT]
import {chromium} from 'playwright-core';
import {spawn} from 'node:child_process';
import {createHash} from 'node:crypto';
import {readFileSync} from 'node:fs';
import {fileURLToPath} from 'node:url';
import path from 'node:path';

const [image, method, density, shot, save, port = '8731'] = process.argv.slice(2);
const web = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const server = spawn('python3', ['-m', 'http.server', port, '--bind', '127.0.0.1', '--directory', web], {stdio: 'ignore'});
let code = 1;
try {
    await new Promise((r) => setTimeout(r, 800));
    const browser = await chromium.launch({executablePath: process.env.CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox']});
    const page = await browser.newPage({viewport: {width: 1280, height: 800}, acceptDownloads: true});
    page.on('pageerror', (e) => console.error('page error:', e.message));
    await page.goto(`http://127.0.0.1:${port}/index.html`);
    await page.setInputFiles('#file', image);
    await page.waitForFunction(() => !document.getElementById('run').disabled);
    await page.selectOption('#method', method);
    await page.fill('#density', density);
    await page.click('#run');
    await page.waitForFunction(() => document.getElementById('psnr') || document.getElementById('status').textContent.startsWith('error'), null, {timeout: 600000});
    const status = await page.textContent('#status');
    if (status.startsWith('error')) throw new Error(status);
    const psnr = await page.textContent('#psnr'), vertices = await page.textContent('#vertices');
    const ms = await page.evaluate(() => document.getElementById('status').textContent.match(/([0-9.]+) s$/)[1] * 1000);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-model')]);
    const bytes = readFileSync(await download.path());
    if (save) await download.saveAs(save);
    await page.screenshot({path: shot, fullPage: true});
    console.log(`page: vertices ${vertices} psnr ${psnr} model-bytes ${bytes.length} model-sha256 ${createHash('sha256').update(bytes).digest('hex')} ms ${Math.round(ms)}`);
    await browser.close();
    code = 0;
} catch (e) {
    console.error('FAIL:', e.message);
} finally {
    server.kill();
}
process.exit(code);
