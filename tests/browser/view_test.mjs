// view_test.mjs — the replay page of `handspring view --html` in headless Chromium (check.sh runs
// it). For each page: it loads from its own file and asks for nothing else (every request must be
// file:, blob: or data:), no console error and no page error, the title names the scenario file,
// the view is not blank (pixel spread of a screenshot), the timeline shows the contact states that
// the run's data has, the objects in those colours and the hand in the view (a check point red
// exactly when one touches), the stylus and the spring in a spring world, and a legend; it opens at
// the frame nearest --html-at. A mouse drag turns the view, the wheel zooms, a right-drag pans
// (each changes the screenshot); the time slider moved to its end changes the screenshot, the
// timeline marker's place and frame and the clock; step back and step move one frame; play moves on
// and pause stops; play at 4x moves further than at 0.1x in the same time (a clock the test drives).
//   node view_test.mjs NODE_MODULES OUTDIR PAGE.html...
import { createRequire } from 'node:module';
import { writeFileSync } from 'node:fs';
import { basename, resolve } from 'node:path';
import { inflateSync } from 'node:zlib';

const [nodeModules, outDir, ...pages] = process.argv.slice(2);
const puppeteer = createRequire(resolve(nodeModules) + '/')('puppeteer-core');
let passed = 0, failed = 0;
function check(ok, what) {
	if (ok) { passed++; console.log(`  ok   ${what}`); }
	else { failed++; console.log(`  FAIL ${what}`); }
}

// A PNG as RGBA rows (8-bit, not interlaced: what Chromium's screenshots are).
function decodePng(buf) {
	let p = 8, width = 0, height = 0, type = 0;
	const idat = [];
	while (p < buf.length) {
		const len = buf.readUInt32BE(p), kind = buf.toString('latin1', p + 4, p + 8), data = buf.subarray(p + 8, p + 8 + len);
		if (kind === 'IHDR') { width = data.readUInt32BE(0); height = data.readUInt32BE(4); type = data[9]; }
		if (kind === 'IDAT') idat.push(data);
		p += 12 + len;
	}
	const bpp = type === 6 ? 4 : 3, raw = inflateSync(Buffer.concat(idat)), stride = width * bpp;
	const out = Buffer.alloc(width * height * 4), prev = Buffer.alloc(stride), cur = Buffer.alloc(stride);
	for (let y = 0; y < height; ++y) {
		const f = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
		for (let x = 0; x < stride; ++x) {
			const a = x >= bpp ? cur[x - bpp] : 0, b = prev[x], c = x >= bpp ? prev[x - bpp] : 0;
			const pa = Math.abs(b - c), pb = Math.abs(a - c), pc = Math.abs(a + b - 2 * c);
			const pred = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][f];
			cur[x] = (line[x] + pred) & 255;
		}
		for (let x = 0; x < width; ++x)
			for (let k = 0; k < 4; ++k) out[4 * (y * width + x) + k] = k < bpp ? cur[x * bpp + k] : 255;
		cur.copy(prev);
	}
	return { width, height, rgba: out };
}
// The spread of the grey levels (standard deviation) and the number of distinct colours.
function spread(img) {
	let s = 0, s2 = 0;
	const colours = new Set();
	const n = img.width * img.height;
	for (let i = 0; i < n; ++i) {
		const r = img.rgba[4 * i], g = img.rgba[4 * i + 1], b = img.rgba[4 * i + 2], v = (r + g + b) / 3;
		s += v; s2 += v * v;
		colours.add((r >> 3) << 10 | (g >> 3) << 5 | b >> 3);
	}
	return { sd: Math.sqrt(Math.max(0, s2 / n - (s / n) ** 2)), colours: colours.size };
}
// Pixels by colour family: the four contact states (blue, orange, green, purple) and the hand's
// skin (an orange far less saturated), by hue and saturation, so shading does not matter.
function families(img) {
	const n = { 0: 0, 1: 0, 2: 0, 3: 0, skin: 0, red: 0, dark: 0 };
	for (let i = 0; i < img.rgba.length; i += 4) {
		const r = img.rgba[i], g = img.rgba[i + 1], b = img.rgba[i + 2], max = Math.max(r, g, b), min = Math.min(r, g, b);
		if (max < 100 && max - min < 12) n.dark++; // dark grey: the stylus and the spring
		if (max < 90 || max - min < 0.3 * max) continue; // grey, or dark (the objects' edges)
		const d = max - min, sat = d / max;
		let hue = max === r ? ((g - b) / d) * 60 : max === g ? ((b - r) / d + 2) * 60 : ((r - g) / d + 4) * 60;
		if (hue < 0) hue += 360;
		if (hue >= 195 && hue <= 225) n[0]++;
		else if (hue >= 15 && hue <= 40 && sat > 0.7) n[1]++;
		else if (hue >= 110 && hue <= 150) n[2]++;
		else if (hue >= 290 && hue <= 330) n[3]++;
		else if (hue >= 10 && hue <= 35 && sat <= 0.62) n.skin++;
		else if ((hue >= 345 || hue <= 6) && sat > 0.65) n.red++; // a check point touching
	}
	return n;
}
const statesOf = fr => new Set(fr.o.filter((_, k) => k % 8 === 7));

// The share of pixels that differ by more than a little between two pictures of the same size.
function changed(a, b) {
	if (a.width !== b.width || a.height !== b.height) return 1;
	let n = 0;
	for (let i = 0; i < a.rgba.length; i += 4)
		if (Math.abs(a.rgba[i] - b.rgba[i]) + Math.abs(a.rgba[i + 1] - b.rgba[i + 1]) + Math.abs(a.rgba[i + 2] - b.rgba[i + 2]) > 24) n++;
	return n / (a.width * a.height);
}

const browser = await puppeteer.launch({
	executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
	headless: true,
	args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1100,800'],
});
try {
	for (const file of pages)
		await testPage(file);
} finally {
	await browser.close();
}
console.log(`check-browser: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);

async function testPage(file) {
	const name = basename(file, '.html');
	console.log(`${file}:`);
	const page = await browser.newPage();
	await page.setViewport({ width: 1100, height: 800 });
	const problems = [];
	page.on('console', m => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
	page.on('pageerror', e => problems.push(`page error: ${e.message}`));
	page.on('request', r => { if (!/^(file|blob|data):/.test(r.url())) problems.push(`asked the network for ${r.url()}`); });
	page.on('requestfailed', r => problems.push(`request failed: ${r.url()}`));
	await page.goto('file://' + resolve(file), { waitUntil: 'load' });
	await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 }).catch(() => problems.push('the page never said it was ready'));
	const run = await page.evaluate(() => JSON.parse(document.getElementById('run').textContent));
	const settle = async () => { // two rendered frames after the last change
		await page.evaluate(() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r))));
	};
	const view = await page.$('#view canvas');
	const shot = async tag => { // the view's canvas alone: the legend and the hint hidden meanwhile
		await settle();
		await page.evaluate(() => { for (const id of ['legend', 'hint']) document.getElementById(id).style.visibility = 'hidden'; });
		const png = Buffer.from(await page.screenshot({ type: 'png', clip: await view.boundingBox(), captureBeyondViewport: false }));
		await page.evaluate(() => { for (const id of ['legend', 'hint']) document.getElementById(id).style.visibility = ''; });
		writeFileSync(`${outDir}/${name}_${tag}.png`, png);
		return decodePng(png);
	};
	const marker = () => page.evaluate(() => ({
		left: parseFloat(document.getElementById('marker').style.left),
		frame: Number(document.getElementById('marker').dataset.frame),
		clock: document.getElementById('clock').textContent,
	}));

	check((await page.title()).includes(run.file) && run.file.length > 0, `title names the scenario file (${run.file})`);
	const first = await shot('start');
	const s = spread(first);
	check(s.sd > 8 && s.colours > 40, `view is not blank (grey-level spread ${s.sd.toFixed(1)}, ${s.colours} colours)`);
	const seen = (img, fr, tag) => { // every state of the frame in its colour, the others hardly (< 3%
		// of the most seen: antialiased edges); the hand's skin
		const f = families(img), want = statesOf(fr), most = Math.max(f[0], f[1], f[2], f[3]);
		check([0, 1, 2, 3].every(st => want.has(st) ? f[st] > 200 : f[st] < 0.03 * most) && (run.hands === 0 || f.skin > 200),
			`${tag}: objects in the colours of their states {${[...want].join(', ')}}${run.hands ? ', the hand' : ''} (pixels ${JSON.stringify(f)})`);
		if (run.hands) {
			const touching = fr.h.some(h => h && h.touch);
			check(touching ? f.red > 30 : f.red === 0, `${tag}: ${touching ? 'a check point touching, in red' : 'no check point in red: none touches'}`);
		}
		return f;
	};
	let opened = 0; // the page opens at the frame nearest --html-at (the first without)
	run.frames.forEach((fr, k) => { if (Math.abs(fr.t - run.start) < Math.abs(run.frames[opened].t - run.start)) opened = k; });
	if (run.start < 0) opened = 0;
	check((await marker()).frame === run.frames[opened].f, `opens at frame ${run.frames[opened].f} (--html-at ${run.start} s)`);
	const opening = seen(first, run.frames[opened], `frame ${run.frames[opened].f}`);
	if (run.frames[opened].s)
		check(opening.dark > 60, `the stylus is drawn (${opening.dark} dark grey pixels)`);

	// the timeline: every contact state the data has, in its colour, and nothing but the states
	const states = new Set(run.frames.flatMap(fr => fr.o.filter((_, k) => k % 8 === 7)));
	const timelineColours = await page.evaluate(() => {
		const c = document.getElementById('timeline'), g = c.getContext('2d'), seen = new Set();
		const d = g.getImageData(0, 0, c.width, c.height).data;
		for (let i = 0; i < d.length; i += 4) seen.add('#' + [d[i], d[i + 1], d[i + 2]].map(v => v.toString(16).padStart(2, '0')).join(''));
		return [...seen];
	});
	const stateRgb = ['#3b6ea5', '#e07b22', '#2e9e44', '#b03a9a'];
	check([...states].every(st => timelineColours.includes(stateRgb[st])) && stateRgb.every((c, st) => states.has(st) || !timelineColours.includes(c)),
		`timeline shows the run's contact states {${[...states].join(', ')}} in their colours`);
	const legend = await page.$eval('#legend', e => e.textContent);
	check(['no contact', 'push at one point', 'push at several points'].every(t => legend.includes(t)), 'legend names the contact states');

	// the mouse: drag turns, the wheel zooms, a right-drag pans
	const box = await view.boundingBox();
	const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
	await page.mouse.move(cx, cy);
	await page.mouse.down();
	for (let k = 1; k <= 10; ++k) await page.mouse.move(cx + 16 * k, cy + 4 * k);
	await page.mouse.up();
	const turned = await shot('dragged');
	check(changed(first, turned) > 0.02, `a drag turns the view (${(100 * changed(first, turned)).toFixed(1)}% of pixels changed)`);
	await page.mouse.wheel({ deltaY: -400 });
	const zoomed = await shot('zoomed');
	check(changed(turned, zoomed) > 0.02, `the wheel zooms (${(100 * changed(turned, zoomed)).toFixed(1)}% changed)`);
	await page.mouse.move(cx, cy);
	await page.mouse.down({ button: 'right' });
	for (let k = 1; k <= 6; ++k) await page.mouse.move(cx - 12 * k, cy);
	await page.mouse.up({ button: 'right' });
	const panned = await shot('panned');
	check(changed(zoomed, panned) > 0.02, `a right-drag pans (${(100 * changed(zoomed, panned)).toFixed(1)}% changed)`);

	// the time slider, moved with the keyboard to the middle of the first stretch whose contact
	// states differ from the first frame's (the last frame when none does); step, play, pause, speed
	const key = fr => fr.o.filter((_, k) => k % 8 === 7).join();
	let a = run.frames.findIndex(fr => key(fr) !== key(run.frames[0])), b = a;
	while (a >= 0 && b + 1 < run.frames.length && key(run.frames[b + 1]) === key(run.frames[a])) ++b;
	const target = a < 0 ? run.frames.length - 1 : Math.floor((a + b) / 2);
	await page.focus('#time');
	await page.keyboard.press('Home');
	const from = await shot('home');
	const before = await marker();
	for (let k = 0; k < target; ++k) await page.keyboard.press('ArrowRight');
	const after = await marker();
	const moved = await shot('slider');
	check(changed(from, moved) > 0.002, `the slider moves the scene to frame ${run.frames[target].f} (${(100 * changed(from, moved)).toFixed(2)}% changed)`);
	const at = seen(moved, run.frames[target], `frame ${run.frames[target].f}`), home = families(from);
	if (run.frames[0].s && run.frames[0].s.k < 0 && run.frames[target].s.k >= 0)
		check(at.dark > home.dark + 50, `the spring is drawn once an object is on it (${home.dark} -> ${at.dark} dark grey pixels)`);
	check(after.left > before.left + 20 && after.frame === run.frames[target].f && before.frame === run.frames[0].f && after.clock !== before.clock,
		`the timeline marker follows the slider (x ${before.left} -> ${after.left} px, frame ${before.frame} -> ${after.frame})`);
	await page.click('#back');
	check((await marker()).frame === run.frames[target - 1].f, 'step back shows the frame before');
	await page.click('#step');
	check((await marker()).frame === run.frames[target].f, 'step shows the frame after');
	// from here the page's clock and its animation frames are the test's (a frame every 16 ms of
	// that clock): how far play gets in 0.8 s depends on the speed alone, not on how busy the
	// machine is (on a loaded one, real animation frames came too seldom to move at all)
	await page.evaluate(() => {
		let now = performance.now(), queue = [];
		performance.now = () => now;
		window.requestAnimationFrame = cb => queue.push(cb);
		window.hsAdvance = ms => {
			for (let t = 0; t < ms; t += 16) {
				now += 16;
				const due = queue;
				queue = [];
				for (const cb of due) cb(now);
			}
		};
	});
	const played = async (speed, ms) => {
		await page.focus('#time');
		await page.keyboard.press('Home');
		await page.select('#speed', speed);
		await page.click('#play');
		await page.evaluate(t => window.hsAdvance(t), ms);
		if (await page.$eval('#play', b => b.textContent) === 'pause') await page.click('#play'); // not at the end yet
		const at = (await marker()).frame;
		await page.evaluate(() => window.hsAdvance(300));
		return { at, still: (await marker()).frame === at };
	};
	const slow = await played('0.1', 800), fast = await played('4', 800);
	check(slow.at > 0 && slow.still && fast.still, `play moves on and pause stops (0.1x: frame ${slow.at} after 0.8 s)`);
	check(fast.at > 4 * slow.at, `play at 4x goes further than at 0.1x (frame ${fast.at} against ${slow.at})`);
	check(problems.length === 0, `no console error, page error or network request${problems.length ? ': ' + problems.join('; ') : ''}`);
	await page.close();
}
