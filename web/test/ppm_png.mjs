// A binary 8-bit PPM (P6) as an RGB PNG, for the browser test's colour input: the page decodes
// PNG/JPEG with the browser, and erd's own PNG writers draw a mesh or write a reconstruction, not
// a copy of an image. Stored rows (filter 0) in one zlib stream: the bytes do not matter, the
// samples do.
//   node web/test/ppm_png.mjs IN.ppm OUT.png
import {readFileSync, writeFileSync} from 'node:fs';
import zlib from 'node:zlib';

const [input, output] = process.argv.slice(2);
const ppm = readFileSync(input);
// Header: "P6", width, height, maxval, separated by whitespace and '#' comments, one whitespace byte.
let at = 2;
const field = () => {
    for (;;) {
        while (at < ppm.length && /\s/.test(String.fromCharCode(ppm[at]))) ++at;
        if (ppm[at] !== 0x23) break;
        while (at < ppm.length && ppm[at] !== 0x0a) ++at;
    }
    const start = at;
    while (at < ppm.length && ppm[at] >= 0x30 && ppm[at] <= 0x39) ++at;
    return Number(ppm.subarray(start, at).toString());
};
const magic = ppm.subarray(0, 2).toString();
const [width, height, maxval] = [field(), field(), field()];
const raster = ppm.subarray(at + 1, at + 1 + width * height * 3);
if (magic !== 'P6' || maxval !== 255 || !(width > 0 && height > 0) || raster.length !== width * height * 3) {
    console.error(`${input}: not a binary 8-bit PPM this converter reads (P6, maxval 255)`);
    process.exit(1);
}
const rows = Buffer.alloc((width * 3 + 1) * height);
for (let y = 0; y < height; ++y) raster.copy(rows, y * (width * 3 + 1) + 1, y * width * 3, (y + 1) * width * 3);
const chunk = (type, data) => {
    const body = Buffer.concat([Buffer.from(type), data]);
    const head = Buffer.alloc(4), tail = Buffer.alloc(4);
    head.writeUInt32BE(data.length);
    tail.writeUInt32BE(zlib.crc32(body));
    return Buffer.concat([head, body, tail]);
};
const ihdr = Buffer.alloc(13);
ihdr.writeUInt32BE(width, 0);
ihdr.writeUInt32BE(height, 4);
ihdr.set([8, 2, 0, 0, 0], 8);  // 8 bits, RGB, deflate, filter set 0, no interlace
writeFileSync(output, Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), chunk('IHDR', ihdr),
                                     chunk('IDAT', zlib.deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]));
