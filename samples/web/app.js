// The samples page: every catalogue scene drawn through the engine's debug draw on a canvas, with
// the methods selectable, a mouse drag, and the readouts the `tumble` program prints.
//
// window.tumbleApp is the page's state; the browser test (tests/web/test_page.py) drives the page
// through its controls and reads the engine through it.
import { loadTumble, drawFlags } from './tumble.js';

const ui = (id) => document.getElementById(id);
const canvas = ui('view');
const context = canvas.getContext('2d');

/// Step times averaged for the readout: a second of steps at 60 Hz.
const STEP_TIME_WINDOW = 60;
/// Readouts that query the world (the largest penetration collides every touching pair) are
/// refreshed at most this often while the scene plays, in ms.
const READOUT_INTERVAL = 200;

const app = {
	tb: null,
	run: null, // the SceneRun on show
	playing: true,
	camera: { x: 0, y: 0, scale: 20 }, // centre in m, pixels per m (CSS pixels)
	drag: null, // { joint, body } while the mouse drags a body
	ground: null, // a static body in the scene's world that holds the drag joint's frame A
	stepTimes: [],
	lastReadout: 0,
	dirty: true, // the picture needs drawing again (a paused scene is not redrawn each frame)
	ready: false,
	error: null,
};
window.tumbleApp = app;

// ---------------------------------------------------------------------------------------------
// Scenes

function methodOptions() {
	return {
		broadPhase: ui('broadPhase').value,
		narrowPhase: ui('narrowPhase').value,
		continuous: ui('continuous').value,
		solver: ui('solver').value,
		subSteps: Number(ui('subSteps').value),
	};
}

/// Builds the selected scene with the selected methods, in place of the one on show.
function loadScene() {
	endDrag();
	if (app.run) app.run.destroy();
	app.ground = null;
	app.run = app.tb.loadScene(ui('scene').value, methodOptions());
	const entry = app.scenes.find((s) => s.name === app.run.name);
	ui('description').textContent = entry ? entry.description : '';
	app.stepTimes = [];
	fitCamera(app.run.bounds());
	refreshReadouts();
	render();
}

function stepOnce() {
	const start = performance.now();
	app.run.step();
	app.stepTimes.push(performance.now() - start);
	if (app.stepTimes.length > STEP_TIME_WINDOW) app.stepTimes.shift();
}

// ---------------------------------------------------------------------------------------------
// Camera: world metres to canvas pixels, y up

function fitCamera(bounds) {
	const width = bounds[1][0] - bounds[0][0], height = bounds[1][1] - bounds[0][1];
	const margin = Math.max(0.5, 0.1 * Math.max(width, height));
	app.camera.x = 0.5 * (bounds[0][0] + bounds[1][0]);
	app.camera.y = 0.5 * (bounds[0][1] + bounds[1][1]);
	app.camera.scale = Math.min(canvas.clientWidth / (width + 2 * margin), canvas.clientHeight / (height + 2 * margin));
}

/// Canvas pixels (CSS, from the canvas's top left) of a world point.
function toScreen(p) {
	const c = app.camera;
	return [canvas.clientWidth / 2 + (p[0] - c.x) * c.scale, canvas.clientHeight / 2 - (p[1] - c.y) * c.scale];
}

function toWorld(s) {
	const c = app.camera;
	return [c.x + (s[0] - canvas.clientWidth / 2) / c.scale, c.y - (s[1] - canvas.clientHeight / 2) / c.scale];
}

function viewBox() {
	const a = toWorld([0, canvas.clientHeight]), b = toWorld([canvas.clientWidth, 0]);
	return [a, b];
}

app.toScreen = toScreen;
app.toWorld = toWorld;

// ---------------------------------------------------------------------------------------------
// Drawing: the debug-draw callbacks on a 2D canvas

const hex = (color) => '#' + (color | 0).toString(16).padStart(6, '0');
const fillOf = (color) => hex(color) + '80'; // the outline's colour, half opaque

function pathOf(points) {
	context.beginPath();
	points.forEach((p, i) => {
		const s = toScreen(p);
		if (i === 0) context.moveTo(s[0], s[1]);
		else context.lineTo(s[0], s[1]);
	});
	context.closePath();
}

const painter = {
	polygon(points, color) {
		pathOf(points);
		context.strokeStyle = hex(color);
		context.stroke();
	},
	solidPolygon(points, radius, color) {
		pathOf(points);
		context.fillStyle = fillOf(color);
		context.strokeStyle = hex(color);
		if (radius > 0) {
			// A rounded polygon is its core grown by the radius: a round-joined stroke that wide.
			context.save();
			context.lineJoin = 'round';
			context.lineWidth = 2 * radius * app.camera.scale;
			context.strokeStyle = fillOf(color);
			context.stroke();
			context.restore();
		}
		context.fill();
		context.stroke();
	},
	circle(center, radius, color) {
		const s = toScreen(center);
		context.beginPath();
		context.arc(s[0], s[1], radius * app.camera.scale, 0, 2 * Math.PI);
		context.strokeStyle = hex(color);
		context.stroke();
	},
	solidCircle(center, radius, axis, color) {
		const s = toScreen(center);
		context.beginPath();
		context.arc(s[0], s[1], radius * app.camera.scale, 0, 2 * Math.PI);
		context.fillStyle = fillOf(color);
		context.strokeStyle = hex(color);
		context.fill();
		context.stroke();
		const e = toScreen([center[0] + radius * axis[0], center[1] + radius * axis[1]]);
		context.beginPath();
		context.moveTo(s[0], s[1]);
		context.lineTo(e[0], e[1]);
		context.stroke();
	},
	solidCapsule(p1, p2, radius, color) {
		const a = toScreen(p1), b = toScreen(p2);
		const angle = Math.atan2(b[1] - a[1], b[0] - a[0]);
		const r = radius * app.camera.scale;
		context.beginPath();
		context.arc(a[0], a[1], r, angle + 0.5 * Math.PI, angle + 1.5 * Math.PI);
		context.arc(b[0], b[1], r, angle - 0.5 * Math.PI, angle + 0.5 * Math.PI);
		context.closePath();
		context.fillStyle = fillOf(color);
		context.strokeStyle = hex(color);
		context.fill();
		context.stroke();
	},
	line(p1, p2, color) {
		const a = toScreen(p1), b = toScreen(p2);
		context.beginPath();
		context.moveTo(a[0], a[1]);
		context.lineTo(b[0], b[1]);
		context.strokeStyle = hex(color);
		context.stroke();
	},
	transform(p, q) {
		const axisLength = 0.2; // m
		painter.line(p, [p[0] + axisLength * q[0], p[1] + axisLength * q[1]], 0xff0000);
		painter.line(p, [p[0] - axisLength * q[1], p[1] + axisLength * q[0]], 0x00ff00);
	},
	point(p, size, color) {
		const s = toScreen(p);
		context.fillStyle = hex(color);
		context.fillRect(s[0] - 0.5 * size, s[1] - 0.5 * size, size, size);
	},
	string(p, text, color) {
		const s = toScreen(p);
		context.fillStyle = hex(color);
		context.fillText(text, s[0], s[1]);
	},
	bounds(lower, upper, color) {
		const a = toScreen(lower), b = toScreen(upper);
		context.strokeStyle = hex(color);
		context.strokeRect(a[0], b[1], b[0] - a[0], a[1] - b[1]);
	},
};

function drawFlagsChosen() {
	let flags = drawFlags.shapes;
	if (ui('drawJoints').checked) flags |= drawFlags.joints;
	if (ui('drawContacts').checked) flags |= drawFlags.contacts;
	if (ui('drawContactNormals').checked) flags |= drawFlags.contactNormals;
	if (ui('drawBounds').checked) flags |= drawFlags.bounds;
	if (ui('drawMass').checked) flags |= drawFlags.mass;
	return flags;
}

function render() {
	const ratio = window.devicePixelRatio || 1;
	const width = Math.round(canvas.clientWidth * ratio), height = Math.round(canvas.clientHeight * ratio);
	if (canvas.width !== width || canvas.height !== height) {
		canvas.width = width;
		canvas.height = height;
	}
	context.setTransform(ratio, 0, 0, ratio, 0, 0);
	context.fillStyle = '#181c21';
	context.fillRect(0, 0, canvas.clientWidth, canvas.clientHeight);
	context.lineWidth = 1;
	context.font = '11px system-ui, sans-serif';
	app.run.world.draw(painter, viewBox(), drawFlagsChosen());
	if (app.drag) {
		const target = toScreen(app.drag.target);
		context.fillStyle = '#5fa8d3';
		context.beginPath();
		context.arc(target[0], target[1], 4, 0, 2 * Math.PI);
		context.fill();
	}
}

// ---------------------------------------------------------------------------------------------
// Readouts: what `tumble run` prints, live

function refreshReadouts() {
	const run = app.run;
	const settings = run.settings();
	const readouts = run.readouts();
	const counters = run.world.getCounters();
	const times = app.stepTimes;
	const mean = times.length > 0 ? times.reduce((a, b) => a + b, 0) / times.length : 0;
	ui('stepIndex').textContent = `${settings.stepIndex} (${settings.subSteps} sub-steps)`;
	ui('stepTime').textContent = times.length > 0 ? `${mean.toFixed(3)} ms` : '–';
	ui('bodies').textContent = `${counters.bodyCount} (${readouts.awakeBodies})`;
	ui('contacts').textContent = `${counters.contactCount} (${counters.touchingCount})`;
	ui('penetration').textContent = `${readouts.largestPenetration.toFixed(6)} m`;
	ui('energy').textContent = `${readouts.kineticEnergy.toPrecision(6)} J`;
	ui('hash').textContent = run.world.getStateHash();
	ui('bytes').textContent = `${(app.tb.getByteCount() / 1024).toFixed(1)} KiB`;
	ui('play').textContent = app.playing ? 'Pause' : 'Play';
	app.lastReadout = performance.now();
}

// ---------------------------------------------------------------------------------------------
// Mouse drag, as Box2D v3.2's samples drag: a motor joint from a static body to the picked body,
// whose linear spring pulls the picked point toward the pointer.

/// The spring's stiffness and cap: 7.5 Hz critically damped, at most 100 times the body's weight
/// under 10 m/s² (a reference acceleration, so that bodies drag in scenes without gravity too).
const DRAG_HERTZ = 7.5;
const DRAG_FORCE_SCALE = 100;
const DRAG_ACCELERATION = 10;

function pointerWorld(event) {
	const r = canvas.getBoundingClientRect();
	return toWorld([event.clientX - r.left, event.clientY - r.top]);
}

function beginDrag(point) {
	const world = app.run.world;
	const body = world.bodyAtPoint(point);
	if (body === null) return false;
	if (app.ground === null) app.ground = world.createBody({ type: 'static' });
	const mass = body.getMass();
	const weight = mass * DRAG_ACCELERATION;
	// Resist spinning with a torque that grows with the body's size (the radius of gyration).
	const lever = mass > 0 ? Math.sqrt(body.getRotationalInertia() / mass) : 0;
	const joint = world.createMotorJoint(app.ground, body, point, {
		linearHertz: DRAG_HERTZ, linearDampingRatio: 1, maxSpringForce: DRAG_FORCE_SCALE * weight,
		maxVelocityTorque: 0.25 * lever * weight,
	});
	if (joint === null) return false;
	app.drag = { joint, body, target: point };
	return true;
}

function moveDrag(point) {
	app.drag.target = point;
	app.drag.joint.setTargetA(point);
	invalidate();
}

function endDrag() {
	if (app.drag) {
		app.drag.joint.destroy();
		app.drag = null;
		invalidate();
	}
}

canvas.addEventListener('pointerdown', (event) => {
	if (event.button === 0 && beginDrag(pointerWorld(event))) canvas.setPointerCapture(event.pointerId);
});
canvas.addEventListener('pointermove', (event) => {
	if (app.drag) moveDrag(pointerWorld(event));
});
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);
canvas.addEventListener('wheel', (event) => {
	event.preventDefault();
	const r = canvas.getBoundingClientRect();
	const s = [event.clientX - r.left, event.clientY - r.top];
	const before = toWorld(s);
	app.camera.scale *= Math.exp(-0.001 * event.deltaY);
	const after = toWorld(s);
	app.camera.x += before[0] - after[0];
	app.camera.y += before[1] - after[1];
	invalidate();
}, { passive: false });

// ---------------------------------------------------------------------------------------------
// Controls and the frame loop

app.pause = () => { app.playing = false; refreshReadouts(); };
app.play = () => { app.playing = true; };
/// Steps the scene on show `count` times, as Step does, and refreshes the page.
app.stepScene = (count) => {
	for (let i = 0; i < count; ++i) stepOnce();
	refreshReadouts();
	render();
	return app.run.world.getStateHash();
};
app.render = render;

/// Marks the picture out of date: a paused scene is drawn again only then.
function invalidate() {
	app.dirty = true;
}

function frame() {
	if (app.playing) {
		stepOnce();
		if (performance.now() - app.lastReadout > READOUT_INTERVAL) refreshReadouts();
		app.dirty = true;
	}
	if (app.dirty) {
		render();
		app.dirty = false;
	}
	requestAnimationFrame(frame);
}

function showError(error) {
	app.error = String(error && error.stack ? error.stack : error);
	ui('description').textContent = `Error: ${error}`;
	console.error(error);
}

async function start() {
	app.tb = await loadTumble();
	app.scenes = app.tb.sceneList();
	for (const s of app.scenes) ui('scene').add(new Option(s.name, s.name));
	const wanted = new URLSearchParams(location.search).get('scene');
	ui('scene').value = app.scenes.some((s) => s.name === wanted) ? wanted : 'pyramid';
	if (new URLSearchParams(location.search).get('paused') !== null) app.playing = false;

	for (const id of ['scene', 'broadPhase', 'narrowPhase', 'continuous', 'solver', 'subSteps']) {
		ui(id).addEventListener('change', loadScene);
	}
	ui('reset').addEventListener('click', loadScene);
	for (const id of ['drawContacts', 'drawContactNormals', 'drawBounds', 'drawJoints', 'drawMass']) {
		ui(id).addEventListener('change', invalidate);
	}
	ui('play').addEventListener('click', () => { app.playing = !app.playing; refreshReadouts(); });
	ui('step').addEventListener('click', () => { app.playing = false; app.stepScene(1); });
	window.addEventListener('resize', () => { fitCamera(app.run.bounds()); render(); });

	loadScene();
	app.ready = true;
	requestAnimationFrame(frame);
}

start().catch(showError);
