// viewer.js — the replay page of `handspring view --html` (page.html; tool/view_html.c writes the
// run as JSON). three.js sits inline as text: each file becomes a blob module and its imports are
// pointed at the blob it needs, so the page loads nothing from outside itself.
const text = id => document.getElementById(id).textContent;
const blobUrl = source => URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
function rewire(source, from, to) {
	if (!source.includes(from))
		throw new Error(`viewer: the vendored file has no ${from} to point at its blob`);
	return source.split(from).join(to);
}
const coreUrl = blobUrl(text('three-core'));
const threeUrl = blobUrl(rewire(text('three-module'), '"./three.core.min.js"', JSON.stringify(coreUrl)));
const orbitUrl = blobUrl(rewire(text('orbit-controls'), "from 'three'", `from ${JSON.stringify(threeUrl)}`));
const THREE = await import(threeUrl);
const { OrbitControls } = await import(orbitUrl);
const run = JSON.parse(text('run'));

// Objects by contact state, as the gnuplot views and docs colour them (docs/model.md §3, Fig. 2).
const STATE = [
	{ name: 'no contact', rgb: 0x3b6ea5 },
	{ name: 'push at one point', rgb: 0xe07b22 },
	{ name: run.model === 'spring' ? 'on the spring' : 'grasp', rgb: 0x2e9e44 },
	{ name: 'push at several points', rgb: 0xb03a9a },
];
const SKIN = 0xc98e6b, POINT = 0x7a4b2e, TOUCHING = 0xd62728, STYLUS = 0x333333, SPRING = 0x555555, CANDIDATE = 0xd4a800;
const css = rgb => '#' + rgb.toString(16).padStart(6, '0');
const frames = run.frames;
const view = document.getElementById('view');

// --- the scene (z up, metres) -------------------------------------------------------------------
let renderer;
try {
	renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
} catch (e) {
	document.getElementById('message').textContent = 'This browser cannot draw WebGL: ' + e.message;
	throw e;
}
renderer.setPixelRatio(window.devicePixelRatio);
view.prepend(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xfbfbfa);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8a80, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(-0.4, -0.6, 1.0);
scene.add(sun);
THREE.Object3D.DEFAULT_UP.set(0, 0, 1);
const camera = new THREE.PerspectiveCamera(40, 1, 0.001, 1000);
camera.up.set(0, 0, 1);

function bounds() {
	const box = new THREE.Box3();
	const p = new THREE.Vector3(), q = new THREE.Quaternion();
	for (const fr of frames) {
		run.objects.forEach((ob, i) => {
			const o = fr.o.slice(8 * i, 8 * i + 8);
			q.set(o[4], o[5], o[6], o[3]);
			for (let k = 0; k < ob.v.length; k += 3)
				box.expandByPoint(p.set(ob.v[k], ob.v[k + 1], ob.v[k + 2]).applyQuaternion(q).add(new THREE.Vector3(o[0], o[1], o[2])));
		});
		for (const h of fr.h)
			for (let k = 0; k < h.p.length; k += 3)
				box.expandByPoint(p.set(h.p[k], h.p[k + 1], h.p[k + 2]));
		if (fr.s)
			box.expandByPoint(p.fromArray(fr.s.p));
	}
	if (run.walls) {
		box.expandByPoint(p.set(run.walls[0], run.walls[2], 0));
		box.expandByPoint(p.set(run.walls[1], run.walls[3], run.walls[4]));
	}
	box.expandByPoint(p.set(box.min.x, box.min.y, 0)); // the floor under it all
	return box;
}
const box = bounds();
const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
const reach = Math.max(size.x, size.y, size.z, 0.1);

// The floor (z = 0): a faint plane and a grid at a round spacing; the walls of a spring world.
function floor() {
	let step = Math.pow(10, Math.floor(Math.log10(reach / 5)));
	while (1.6 * reach / step > 14) step *= 2;
	const n = Math.ceil(0.8 * reach / step), x0 = Math.round(centre.x / step) * step, y0 = Math.round(centre.y / step) * step;
	const pts = [];
	for (let k = -n; k <= n; ++k) {
		pts.push(x0 + k * step, y0 - n * step, 0, x0 + k * step, y0 + n * step, 0);
		pts.push(x0 - n * step, y0 + k * step, 0, x0 + n * step, y0 + k * step, 0);
	}
	const g = new THREE.BufferGeometry();
	g.setAttribute('position', new THREE.Float32BufferAttribute(pts, 3));
	scene.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0xb8b8b8 })));
	const plane = new THREE.Mesh(new THREE.PlaneGeometry(2 * n * step, 2 * n * step),
		new THREE.MeshBasicMaterial({ color: 0xe9e9e4, transparent: true, opacity: 0.6, depthWrite: false, side: THREE.DoubleSide }));
	plane.position.set(x0, y0, -1e-4);
	scene.add(plane);
}
function walls() {
	if (!run.walls) return;
	const [x0, x1, y0, y1, h] = run.walls;
	const c = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]], pts = [];
	for (let k = 0; k < 4; ++k) {
		const [a, b] = [c[k], c[(k + 1) % 4]];
		pts.push(a[0], a[1], 0, b[0], b[1], 0, a[0], a[1], h, b[0], b[1], h, a[0], a[1], 0, a[0], a[1], h);
		const side = new THREE.Mesh(new THREE.PlaneGeometry(Math.hypot(b[0] - a[0], b[1] - a[1]), h),
			new THREE.MeshBasicMaterial({ color: 0x808080, transparent: true, opacity: 0.12, depthWrite: false, side: THREE.DoubleSide }));
		side.position.set((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, h / 2);
		side.rotation.set(Math.PI / 2, 0, Math.atan2(b[1] - a[1], b[0] - a[0]), 'ZXY');
		scene.add(side);
	}
	const g = new THREE.BufferGeometry();
	g.setAttribute('position', new THREE.Float32BufferAttribute(pts, 3));
	scene.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x707070 })));
}
floor();
walls();

// An object's faces (polygons, maybe not convex) triangulated in their own plane, in its frame.
function shapeGeometry(ob) {
	const v = k => new THREE.Vector3(ob.v[3 * k], ob.v[3 * k + 1], ob.v[3 * k + 2]);
	const pos = [];
	for (const face of ob.f) {
		const p = face.map(v), n = new THREE.Vector3();
		for (let k = 0; k < p.length; ++k) { // Newell's normal
			const a = p[k], b = p[(k + 1) % p.length];
			n.x += (a.y - b.y) * (a.z + b.z); n.y += (a.z - b.z) * (a.x + b.x); n.z += (a.x - b.x) * (a.y + b.y);
		}
		n.normalize();
		const u = new THREE.Vector3().subVectors(p[1], p[0]).normalize(), w = new THREE.Vector3().crossVectors(n, u);
		const flat = p.map(q => new THREE.Vector2(q.dot(u), q.dot(w)));
		for (const t of THREE.ShapeUtils.triangulateShape(flat, []))
			for (const k of t) pos.push(p[k].x, p[k].y, p[k].z);
	}
	const g = new THREE.BufferGeometry();
	g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
	g.computeVertexNormals();
	return g;
}
const objects = run.objects.map(ob => {
	const g = shapeGeometry(ob);
	const mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ color: STATE[0].rgb, side: THREE.DoubleSide,
		polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
	mesh.add(new THREE.LineSegments(new THREE.EdgesGeometry(g, 20), new THREE.LineBasicMaterial({ color: 0x1d2b3a })));
	scene.add(mesh);
	return mesh;
});

// The hands: 15 finger segments (check point s to s + 1 of each finger), the 20 check points (red
// where they touch an object), the palm through the fingers' bases.
const unitCylinder = new THREE.CylinderGeometry(1, 1, 1, 10);
unitCylinder.translate(0, 0.5, 0);
const unitSphere = new THREE.SphereGeometry(1, 12, 8);
function stick(colour) {
	const m = new THREE.Mesh(unitCylinder, new THREE.MeshLambertMaterial({ color: colour }));
	scene.add(m);
	return m;
}
function ball(colour, r) {
	const m = new THREE.Mesh(unitSphere, new THREE.MeshLambertMaterial({ color: colour }));
	m.scale.setScalar(r);
	scene.add(m);
	return m;
}
const Y = new THREE.Vector3(0, 1, 0);
function placeStick(m, a, b, r) {
	const d = new THREE.Vector3().subVectors(b, a), len = d.length();
	m.position.copy(a);
	m.quaternion.setFromUnitVectors(Y, len > 0 ? d.divideScalar(len) : Y);
	m.scale.set(r, Math.max(len, 1e-6), r);
	m.visible = true;
}
const hands = Array.from({ length: run.hands }, () => {
	const palmGeometry = new THREE.BufferGeometry();
	palmGeometry.setAttribute('position', new THREE.Float32BufferAttribute(new Array(9 * 3).fill(0), 3));
	const palm = new THREE.Mesh(palmGeometry, new THREE.MeshLambertMaterial({ color: 0xe0b392, side: THREE.DoubleSide,
		transparent: true, opacity: 0.75 }));
	scene.add(palm);
	return {
		segments: Array.from({ length: 15 }, () => stick(SKIN)),
		points: Array.from({ length: 20 }, () => ball(POINT, 0.0065)), // wider than the segments: seen at the joints
		palm,
	};
});
const contacts = [];
const stylus = { rod: stick(STYLUS), tip: ball(STYLUS, 0.008), spring: null };
const candidate = new THREE.BoxHelper(undefined, CANDIDATE);
scene.add(candidate);

function coil(a, g) { // 8 turns of 1 cm radius from the spring's anchor to G
	const d = new THREE.Vector3().subVectors(g, a), len = d.length();
	const u = len > 0 ? d.clone().divideScalar(len) : new THREE.Vector3(0, 0, -1);
	const e1 = new THREE.Vector3().crossVectors(u, Math.abs(u.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : Y).normalize();
	const e2 = new THREE.Vector3().crossVectors(u, e1), pts = [];
	for (let k = 0; k <= 160; ++k) {
		const s = k / 160, phi = 2 * Math.PI * 8 * s;
		pts.push(a.clone().addScaledVector(d, s).addScaledVector(e1, 0.01 * Math.cos(phi)).addScaledVector(e2, 0.01 * Math.sin(phi)));
	}
	return new THREE.TubeGeometry(new THREE.CatmullRomCurve3(pts), 320, 0.0025, 6);
}

// --- one frame --------------------------------------------------------------------------------
let index = 0;
const v3 = (a, k = 0) => new THREE.Vector3(a[k], a[k + 1], a[k + 2]);
function showHands(fr) {
	hands.forEach((hand, h) => {
		const data = fr.h[h];
		hand.segments.forEach(m => { m.visible = false; });
		hand.points.forEach(m => { m.visible = false; });
		hand.palm.visible = !!data;
		if (!data) return;
		const p = k => v3(data.p, 3 * k);
		for (let f = 0; f < 5; ++f)
			for (let s = 0; s < 3; ++s) placeStick(hand.segments[3 * f + s], p(4 * f + s), p(4 * f + s + 1), 0.005);
		hand.points.forEach((m, k) => {
			m.position.copy(p(k));
			m.material.color.setHex(data.touch >> k & 1 ? TOUCHING : POINT);
			m.visible = true;
		});
		const pos = hand.palm.geometry.attributes.position; // a fan from the thumb's base
		for (let t = 0; t < 3; ++t)
			[0, 4 * (t + 1), 4 * (t + 2)].forEach((k, j) => pos.setXYZ(3 * t + j, data.p[3 * k], data.p[3 * k + 1], data.p[3 * k + 2]));
		pos.needsUpdate = true;
		hand.palm.geometry.computeVertexNormals();
	});
}
function showContacts(fr) {
	const n = fr.c.length / 4;
	while (contacts.length < n) contacts.push(ball(0, 0.004));
	contacts.forEach((m, k) => {
		m.visible = k < n;
		if (k < n) {
			m.position.set(fr.c[4 * k], fr.c[4 * k + 1], fr.c[4 * k + 2]);
			m.material.color.setHex(STATE[fr.o[8 * fr.c[4 * k + 3] + 7]].rgb);
		}
	});
}
function showStylus(fr) {
	const s = fr.s;
	stylus.rod.visible = stylus.tip.visible = !!s;
	if (stylus.spring) {
		scene.remove(stylus.spring);
		stylus.spring.geometry.dispose();
		stylus.spring = null;
	}
	candidate.visible = false;
	if (!s) return;
	const p = v3(s.p);
	placeStick(stylus.rod, p, p.clone().addScaledVector(v3(s.d), 0.1), 0.004);
	stylus.tip.position.copy(p);
	if (s.k >= 0) {
		stylus.spring = new THREE.Mesh(coil(v3(s.a), v3(fr.o, 8 * s.k)), new THREE.MeshLambertMaterial({ color: SPRING }));
		scene.add(stylus.spring);
	}
	if (s.n >= 0) {
		candidate.setFromObject(objects[s.n]);
		candidate.visible = true;
	}
}
function statusText(fr) {
	const parts = [`t = ${fr.t.toFixed(3)} s`];
	run.objects.forEach((ob, i) => {
		const st = fr.o[8 * i + 7];
		if (st) parts.push(`${ob.name}: ${STATE[st].name}`);
	});
	if (fr.s && fr.s.k >= 0) parts.push(`spring extension ${fr.s.e.toFixed(3)} m`);
	return parts.join(' · ');
}
function show(k) {
	index = Math.max(0, Math.min(frames.length - 1, k));
	const fr = frames[index];
	objects.forEach((m, i) => {
		const o = fr.o.slice(8 * i, 8 * i + 8);
		m.position.set(o[0], o[1], o[2]);
		m.quaternion.set(o[4], o[5], o[6], o[3]);
		m.material.color.setHex(STATE[o[7]].rgb);
	});
	showHands(fr);
	showContacts(fr);
	showStylus(fr);
	document.getElementById('status').textContent = statusText(fr);
	document.getElementById('clock').textContent = `t = ${fr.t.toFixed(3)} s · frame ${fr.f} of ${frames[frames.length - 1].f}`;
	slider.value = String(index);
	placeMarker();
	requestRender();
}

// --- camera, controls, drawing -------------------------------------------------------------------
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(centre);
controls.screenSpacePanning = true;
controls.keys = null;
const az = THREE.MathUtils.degToRad(-115), el = THREE.MathUtils.degToRad(28); // from the front left, above
camera.position.copy(centre).addScaledVector(new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)), 1.8 * reach);
controls.update(); // look at the target from there
controls.addEventListener('change', () => requestRender());
let pending = false;
function requestRender() {
	if (pending) return;
	pending = true;
	requestAnimationFrame(() => {
		pending = false;
		renderer.render(scene, camera);
		document.body.dataset.rendered = String(Number(document.body.dataset.rendered || 0) + 1);
	});
}
function resize() { // the canvas fills the view (absolute: its size never moves the layout)
	const w = view.clientWidth, h = view.clientHeight;
	renderer.setSize(w, h);
	camera.aspect = w / Math.max(h, 1);
	camera.updateProjectionMatrix();
	drawTimeline();
	renderer.render(scene, camera); // at once: a resized canvas is blank until drawn
}

// --- playback -----------------------------------------------------------------------------------
const slider = document.getElementById('time'), playButton = document.getElementById('play');
const speed = document.getElementById('speed');
slider.max = String(frames.length - 1);
let playing = false, clock = 0, last = 0;
function setPlaying(on) {
	playing = on;
	playButton.textContent = on ? 'pause' : 'play';
	if (on) {
		if (index >= frames.length - 1) show(0);
		clock = frames[index].t;
		last = performance.now();
		requestAnimationFrame(tick);
	}
}
function tick(now) {
	if (!playing) return;
	clock += (now - last) / 1000 * Number(speed.value);
	last = now;
	let k = index;
	while (k + 1 < frames.length && frames[k + 1].t <= clock) ++k;
	if (k !== index) show(k);
	if (index >= frames.length - 1) setPlaying(false);
	else requestAnimationFrame(tick);
}
playButton.addEventListener('click', () => setPlaying(!playing));
document.getElementById('back').addEventListener('click', () => { setPlaying(false); show(index - 1); });
document.getElementById('step').addEventListener('click', () => { setPlaying(false); show(index + 1); });
slider.addEventListener('input', () => { setPlaying(false); show(Number(slider.value)); });
window.addEventListener('keydown', e => {
	if (e.target === slider || e.target === speed) return;
	if (e.key === ' ') { e.preventDefault(); setPlaying(!playing); }
	if (e.key === 'ArrowLeft') { setPlaying(false); show(index - 1); }
	if (e.key === 'ArrowRight') { setPlaying(false); show(index + 1); }
});

// --- the contact-state timeline: a row per object, its state over the run; the marker follows ----
const timeline = document.getElementById('timeline'), marker = document.getElementById('marker');
const LABEL = 110, ROW = 13;
function timeX(k) {
	const w = timeline.clientWidth - LABEL - 4;
	return LABEL + (frames.length > 1 ? k / (frames.length - 1) : 0) * w;
}
function drawTimeline() {
	const rows = run.objects.length, ratio = window.devicePixelRatio || 1;
	const w = timeline.clientWidth, h = rows * ROW + 16;
	timeline.style.height = h + 'px';
	timeline.width = Math.round(w * ratio);
	timeline.height = Math.round(h * ratio);
	const c = timeline.getContext('2d');
	c.scale(ratio, ratio);
	c.font = '11px system-ui, sans-serif';
	c.textBaseline = 'middle';
	run.objects.forEach((ob, i) => {
		const y = i * ROW;
		c.fillStyle = '#333';
		c.fillText(ob.name.length > 16 ? ob.name.slice(0, 15) + '…' : ob.name, 0, y + ROW / 2);
		let start = 0;
		for (let k = 1; k <= frames.length; ++k) {
			const st = frames[start].o[8 * i + 7];
			if (k < frames.length && frames[k].o[8 * i + 7] === st) continue;
			c.fillStyle = css(STATE[st].rgb);
			c.fillRect(timeX(start), y + 1, Math.max(timeX(k - 1) - timeX(start), 1), ROW - 2);
			start = k;
		}
	});
	c.fillStyle = '#666';
	c.fillText('0 s', LABEL, rows * ROW + 8);
	const end = `${frames[frames.length - 1].t.toFixed(2)} s`;
	c.fillText(end, w - 4 - c.measureText(end).width, rows * ROW + 8);
	marker.style.height = rows * ROW + 'px';
	placeMarker();
}
function placeMarker() {
	marker.style.left = (12 + timeX(index)) + 'px';
	marker.dataset.frame = String(frames[index].f);
}
timeline.addEventListener('click', e => {
	const x = e.offsetX, w = timeline.clientWidth - LABEL - 4;
	if (x < LABEL) return;
	setPlaying(false);
	show(Math.round((x - LABEL) / w * (frames.length - 1)));
});

// --- the legend ---------------------------------------------------------------------------------
function legend() {
	const rows = STATE.map(s => `<div><i style="background:${css(s.rgb)}"></i>${s.name}</div>`);
	rows.push('<hr>');
	if (run.hands > 0) {
		rows.push(`<div><i class="line" style="background:${css(SKIN)}"></i>finger segments, palm</div>`);
		rows.push(`<div><i class="dot" style="background:${css(POINT)}"></i>check points</div>`);
		rows.push(`<div><i class="dot" style="background:${css(TOUCHING)}"></i>check point touching</div>`);
		rows.push('<div><i class="dot" style="background:#888"></i>contact point (its object\'s colour)</div>');
	}
	if (run.model === 'spring') {
		rows.push(`<div><i class="line" style="background:${css(STYLUS)}"></i>stylus (10 cm ray)</div>`);
		rows.push(`<div><i class="line" style="background:${css(SPRING)}"></i>spring: anchor to G</div>`);
		rows.push(`<div><i style="border:2px solid ${css(CANDIDATE)};width:8px;height:8px"></i>selection candidate</div>`);
	}
	if (run.walls) rows.push('<div><i style="background:#c8c8c8"></i>walls</div>');
	rows.push('<div><i class="line" style="background:#b8b8b8"></i>floor (z = 0)</div>');
	document.getElementById('legend').innerHTML = rows.join('');
}

legend();
new ResizeObserver(resize).observe(view);
resize();
let first = 0; // the frame nearest the time the page opens at (--html-at)
frames.forEach((fr, k) => { if (Math.abs(fr.t - run.start) < Math.abs(frames[first].t - run.start)) first = k; });
show(run.start < 0 ? 0 : first);
document.body.dataset.ready = '1';
