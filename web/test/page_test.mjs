// Browser test of the page: Debian's chromium, driven by playwright-core, against `make serve`'s
// server (started here). For each job: loads the page afresh, sets the image, sets the form's controls,
// runs, reads the PSNR and vertex count the page shows, the largest progress percentage it drew
// and the downloaded model, and prints
// "page: vertices N psnr P model-bytes B model-sha256 H ms T progress-max Q" for
// tests/web_test.sh to compare with the native erd. Screenshot of the last job's page: SHOT.
//   node web/test/page_test.mjs SHOT JOB... [env PORT]
// JOB: IMAGE,METHOD,DENSITY,MODEL_COPY[,id=value...] (ids of the form's controls: edges, wedge-fit,
// wedge-rule, psnr-stop, max-error; thesis=1 and gray=1 check those boxes; svg=FILE and png=FILE
// also save the vector SVG and the reconstruction PNG the page offers). The line then adds
// "channels C" (what the status says: 1 gray, 3 colour) and "files-ms F" (the time the worker took
// to write the downloads after the mesh; T is the mesh's and its reconstruction's).
import {chromium} from 'playwright-core';
import {spawn} from 'node:child_process';
import {createHash} from 'node:crypto';
import {readFileSync} from 'node:fs';
import {fileURLToPath} from 'node:url';
import path from 'node:path';

const [shot, ...jobs] = process.argv.slice(2);
const port = process.env.PORT || '8731';
const web = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const server = spawn('python3', ['-m', 'http.server', port, '--bind', '127.0.0.1', '--directory', web], {stdio: 'ignore'});
let code = 1;
try {
    for (let i = 0; i < 100; ++i) {  // until the server answers (at most 5 s)
        if (await fetch(`http://127.0.0.1:${port}/index.html`).then((r) => r.ok, () => false)) break;
        await new Promise((r) => setTimeout(r, 50));
    }
    const browser = await chromium.launch({executablePath: process.env.CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox']});
    const page = await browser.newPage({viewport: {width: 1280, height: 800}, acceptDownloads: true});
    page.on('pageerror', (e) => console.error('page error:', e.message));
    for (const job of jobs) {
        await page.goto(`http://127.0.0.1:${port}/index.html`);  // the form's defaults for every job
        const [image, method, density, save, ...controls] = job.split(',');
        await page.setInputFiles('#file', image);
        await page.waitForFunction(() => !document.getElementById('run').disabled);
        await page.selectOption('#method', method);
        await page.fill('#density', density);
        const saves = {};
        for (const c of controls) {
            const [id, value] = c.split('=');
            if (id === 'svg' || id === 'png') saves[id] = value;
            else if (id === 'thesis' || id === 'gray') await page.setChecked('#' + id, value === '1');
            else if (await page.evaluate((i) => document.getElementById(i).tagName, id) === 'SELECT') await page.selectOption('#' + id, value);
            else await page.fill('#' + id, value);
        }
        await page.click('#run');
        await page.waitForFunction(() => document.getElementById('psnr') || document.getElementById('status').textContent.startsWith('error'), null, {timeout: 600000});
        const status = await page.textContent('#status');
        if (status.startsWith('error')) throw new Error(status);
        const psnr = await page.textContent('#psnr'), vertices = await page.textContent('#vertices');
        const ms = await page.evaluate(() => document.getElementById('status').textContent.match(/([0-9.]+) s$/)[1] * 1000);
        const progressMax = await page.evaluate(() => document.getElementById('bar').dataset.max);
        await page.waitForFunction(() => !document.getElementById('dl-model').hidden, null, {timeout: 600000});  // files after the mesh
        const filesMs = await page.evaluate(() => [...document.getElementById('timings').rows]
            .find((r) => r.cells[0].textContent === 'files in the worker').cells[1].textContent);
        const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-model')]);
        const bytes = readFileSync(await download.path());
        if (save) await download.saveAs(save);
        for (const [id, file] of Object.entries(saves)) {
            await page.waitForFunction((i) => !document.getElementById(i).hidden, 'dl-' + id);  // the PNG is encoded after the rest
            const [d] = await Promise.all([page.waitForEvent('download'), page.click('#dl-' + id)]);
            await d.saveAs(file);
        }
        const channels = status.includes('colour') ? 3 : 1;
        console.log(`page: vertices ${vertices} psnr ${psnr} model-bytes ${bytes.length} model-sha256 ${createHash('sha256').update(bytes).digest('hex')} ms ${Math.round(ms)} progress-max ${progressMax} channels ${channels} files-ms ${Math.round(filesMs)}`);
    }
    await page.screenshot({path: shot, fullPage: true});
    await browser.close();
    code = 0;
} catch (e) {
    console.error('FAIL:', e.message);
} finally {
    server.kill();
}
process.exit(code);
