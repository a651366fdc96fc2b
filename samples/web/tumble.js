// Tumble in JavaScript: the WebAssembly module (tumble.wasm, built from the library, the scene
// catalogue and tumble_web.c) behind a small API in the shape of the C API.
//
//   import { loadTumble } from './tumble.js';
//   const tb = await loadTumble();                     // or loadTumble(bytes) outside a page
//   const world = tb.createWorld({ gravity: [0, -10] });
//   const ground = world.createBody({ type: 'static' });
//   ground.createBoxShape(20, 1, { center: [0, -1] });
//   const box = world.createBody({ type: 'dynamic', position: [0, 4] });
//   box.createBoxShape(0.5, 0.5, { density: 1, friction: 0.6 });
//   for (let i = 0; i < 60; ++i) world.step(1 / 60, 4);
//   box.getPosition();                                 // [x, y]
//   world.destroy();                                   // tb.getByteCount() is back where it was
//
// Ids cross as the library's stored forms: a world as a 32-bit number, bodies, shapes and joints
// as 64-bit BigInts (tbStoreBodyId…), wrapped here in objects. The module runs on the page's own
// thread (no workers, no shared memory), so the page needs no special headers.

const bodyTypes = { static: 0, kinematic: 1, dynamic: 2 };

/// Method names as the `tumble` program takes them (--broadphase, --narrowphase, --toi, --solver),
/// to the library's enum values.
export const methods = {
	broadPhase: { auto: 0, tree: 1, sap: 2, brute: 3, hash: 4 },
	narrowPhase: { auto: 0, sat: 1, gjk: 2 },
	continuous: { quadratic: 0, off: 1, ca: 2 },
	solver: { soft: 0, baumgarte: 1, ngs: 2 },
};

/// Debug-draw switches (Web_World_Draw's flags).
export const drawFlags = {
	shapes: 1, joints: 2, contacts: 4, contactNormals: 8, bounds: 16, mass: 32, jointExtras: 64,
	contactForces: 128, frictionForces: 256, islands: 512, graphColors: 1024,
};

function methodValue(table, name) {
	if (name === undefined || name === null || name === 'default') return -1;
	const value = table[name];
	if (value === undefined) throw new Error(`unknown method '${name}' (one of ${Object.keys(table).join(', ')})`);
	return value;
}

/// The few WASI calls the C library makes: the clock (the step's profile), writes to stdout and
/// stderr (the library's error hook), and the stubs of closing and seeking that stdio links in.
function wasiImports(state) {
	const decoder = new TextDecoder();
	const lines = { 1: '', 2: '' };
	return {
		clock_time_get(clockId, precision, out) {
			const nanoseconds = BigInt(Math.round(performance.now() * 1e6));
			new DataView(state.memory.buffer).setBigUint64(out, nanoseconds, true);
			return 0;
		},
		fd_write(fd, iovs, iovCount, written) {
			const view = new DataView(state.memory.buffer);
			let total = 0;
			for (let i = 0; i < iovCount; ++i) {
				const pointer = view.getUint32(iovs + 8 * i, true);
				const length = view.getUint32(iovs + 8 * i + 4, true);
				lines[fd] = (lines[fd] || '') + decoder.decode(new Uint8Array(state.memory.buffer, pointer, length));
				total += length;
			}
			let end;
			while ((end = lines[fd].indexOf('\n')) >= 0) {
				const line = lines[fd].slice(0, end);
				lines[fd] = lines[fd].slice(end + 1);
				(fd === 2 ? state.onError : state.onPrint)(line);
			}
			view.setUint32(written, total, true);
			return 0;
		},
		fd_close() { return 8; }, // EBADF: the module opens no file
		fd_seek() { return 70; }, // ESPIPE
	};
}

/// Loads tumble.wasm: `source` is its URL (default: beside this file) or its bytes.
/// options.onError receives the library's error messages (default console.error).
export async function loadTumble(source, options = {}) {
	const state = {
		memory: null,
		onPrint: options.onPrint || ((line) => console.log(line)),
		onError: options.onError || ((line) => console.error(line)),
	};
	const imports = { wasi_snapshot_preview1: wasiImports(state) };
	let instance;
	if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) {
		instance = (await WebAssembly.instantiate(source, imports)).instance;
	} else {
		const url = source || new URL('tumble.wasm', import.meta.url);
		const response = await fetch(url);
		if (!response.ok) throw new Error(`cannot load ${url}: ${response.status}`);
		instance = (await WebAssembly.instantiate(await response.arrayBuffer(), imports)).instance;
	}
	state.memory = instance.exports.memory;
	instance.exports._initialize();
	return new Tumble(instance.exports, state.memory);
}

export class Tumble {
	constructor(exports, memory) {
		this.c = exports;
		this.memory = memory;
		this.scratch = exports.Web_Scratch();
		this.methods = methods;
		this.drawFlags = drawFlags;
	}

	// Views are made on each use: memory growth replaces the buffer under them.
	floats(pointer, count) { return new Float32Array(this.memory.buffer, pointer, count); }
	ints(pointer, count) { return new Int32Array(this.memory.buffer, pointer, count); }
	ids(pointer, count) { return new BigUint64Array(this.memory.buffer, pointer, count); }
	string(pointer) {
		if (pointer === 0) return null;
		const bytes = new Uint8Array(this.memory.buffer, pointer);
		return new TextDecoder().decode(bytes.subarray(0, bytes.indexOf(0)));
	}

	/// Bytes the engine holds (tbGetByteCount): every world, body, contact.
	getByteCount() { return this.c.Web_GetByteCount(); }

	/// def: gravity [x, y] (default [0, −10]), enableSleep (true), broadPhase, narrowPhase,
	/// continuous, solver (names as in `methods`; default: the library's).
	createWorld(def = {}) {
		const g = def.gravity || [0, -10];
		const id = this.c.Web_CreateWorld(g[0], g[1], def.enableSleep === false ? 0 : 1,
			methodValue(methods.broadPhase, def.broadPhase), methodValue(methods.narrowPhase, def.narrowPhase),
			methodValue(methods.continuous, def.continuous), methodValue(methods.solver, def.solver));
		return this.c.Web_World_IsValid(id) ? new World(this, id) : null;
	}

	// The scene catalogue (samples/catalogue.c).

	/// [{ index, name, description }] of every catalogue scene.
	sceneList() {
		const list = [];
		for (let i = 0; i < this.c.Web_SceneCount(); ++i) {
			list.push({ index: i, name: this.string(this.c.Web_SceneName(i)), description: this.string(this.c.Web_SceneDescription(i)) });
		}
		return list;
	}

	/// Builds a catalogue scene as `tumble run NAME` does. options: broadPhase, narrowPhase,
	/// continuous, solver (method names, default the scene's), subSteps (default the scene's).
	loadScene(name, options = {}) {
		const index = this.sceneList().findIndex((s) => s.name === name);
		if (index < 0) throw new Error(`unknown scene '${name}'`);
		const pointer = this.c.Web_LoadScene(index, methodValue(methods.broadPhase, options.broadPhase),
			methodValue(methods.narrowPhase, options.narrowPhase), methodValue(methods.continuous, options.continuous),
			methodValue(methods.solver, options.solver), options.subSteps || 0);
		if (pointer === 0) throw new Error(`scene '${name}' could not be built`);
		return new SceneRun(this, pointer, name);
	}
}

export class World {
	constructor(tb, id) {
		this.tb = tb;
		this.id = id;
	}

	destroy() { this.tb.c.Web_DestroyWorld(this.id); }
	isValid() { return this.tb.c.Web_World_IsValid(this.id) !== 0; }
	step(timeStep, subSteps) { return this.tb.c.Web_World_Step(this.id, timeStep, subSteps) !== 0; }
	/// tbWorld_GetStateHash as 16 hexadecimal digits (a BigInt would lose nothing either; text compares
	/// with the `tumble` program's line).
	getStateHash() { return BigInt.asUintN(64, this.tb.c.Web_World_GetStateHash(this.id)).toString(16).padStart(16, '0'); }
	/// The last step's time, ms.
	getStepTime() { return this.tb.c.Web_World_GetStepTime(this.id); }
	getCounters() {
		this.tb.c.Web_World_GetCounters(this.id);
		const v = this.tb.ints(this.tb.scratch, 5);
		return { bodyCount: v[0], shapeCount: v[1], contactCount: v[2], touchingCount: v[3], jointCount: v[4] };
	}

	/// def: type ('static', 'kinematic', 'dynamic'; default static), position [x, y], angle,
	/// linearVelocity [x, y], angularVelocity, linearDamping, angularDamping, gravityScale,
	/// isBullet, fixedRotation.
	createBody(def = {}) {
		const p = def.position || [0, 0];
		const v = def.linearVelocity || [0, 0];
		const type = bodyTypes[def.type || 'static'];
		if (type === undefined) throw new Error(`unknown body type '${def.type}'`);
		const id = this.tb.c.Web_CreateBody(this.id, type, p[0], p[1], def.angle || 0, v[0], v[1], def.angularVelocity || 0,
			def.linearDamping || 0, def.angularDamping || 0, def.gravityScale ?? 1, def.isBullet ? 1 : 0, def.fixedRotation ? 1 : 0);
		return this.tb.c.Web_Body_IsValid(id) ? new Body(this, id) : null;
	}

	// Joints: anchors are world points. Common options: collideConnected.

	createDistanceJoint(bodyA, bodyB, anchorA, anchorB, o = {}) {
		return this.joint(this.tb.c.Web_CreateDistanceJoint(this.id, bodyA.id, bodyB.id, anchorA[0], anchorA[1], anchorB[0],
			anchorB[1], o.enableSpring ? 1 : 0, o.hertz || 0, o.dampingRatio || 0, o.collideConnected ? 1 : 0));
	}
	createRevoluteJoint(bodyA, bodyB, anchor, o = {}) {
		return this.joint(this.tb.c.Web_CreateRevoluteJoint(this.id, bodyA.id, bodyB.id, anchor[0], anchor[1],
			o.enableLimit ? 1 : 0, o.lowerAngle || 0, o.upperAngle || 0, o.enableMotor ? 1 : 0, o.motorSpeed || 0,
			o.maxMotorTorque || 0, o.collideConnected ? 1 : 0));
	}
	createWeldJoint(bodyA, bodyB, anchor, o = {}) {
		return this.joint(this.tb.c.Web_CreateWeldJoint(this.id, bodyA.id, bodyB.id, anchor[0], anchor[1],
			o.linearHertz || 0, o.angularHertz || 0, o.dampingRatio || 0, o.collideConnected ? 1 : 0));
	}
	createPrismaticJoint(bodyA, bodyB, anchor, axis, o = {}) {
		return this.joint(this.tb.c.Web_CreatePrismaticJoint(this.id, bodyA.id, bodyB.id, anchor[0], anchor[1], axis[0],
			axis[1], o.enableLimit ? 1 : 0, o.lower || 0, o.upper || 0, o.enableMotor ? 1 : 0, o.motorSpeed || 0,
			o.maxMotorForce || 0, o.collideConnected ? 1 : 0));
	}
	/// A motor joint's spring pulls the point `anchor` of body B toward frame A's origin, at
	/// `anchor` too until moved with joint.setTargetA(point).
	createMotorJoint(bodyA, bodyB, anchor, o = {}) {
		return this.joint(this.tb.c.Web_CreateMotorJoint(this.id, bodyA.id, bodyB.id, anchor[0], anchor[1],
			o.linearHertz ?? 5, o.linearDampingRatio ?? 1, o.maxSpringForce ?? 1000, o.maxVelocityTorque || 0));
	}
	joint(id) { return this.tb.c.Web_Joint_IsValid(id) ? new Joint(this, id) : null; }

	// Queries.

	/// The first body with a shape holding the point (dynamic bodies only unless anyType), or null.
	bodyAtPoint(point, anyType = false) {
		const id = this.tb.c.Web_World_BodyAtPoint(this.id, point[0], point[1], anyType ? 0 : 1);
		return this.tb.c.Web_Body_IsValid(id) ? new Body(this, id) : null;
	}
	/// Shapes whose fat boxes overlap the box [[lowerX, lowerY], [upperX, upperY]].
	overlapAABB(box) {
		const count = this.tb.c.Web_World_OverlapAABB(this.id, box[0][0], box[0][1], box[1][0], box[1][1]);
		return Array.from(this.tb.ids(this.tb.scratch, count), (id) => new Shape(this, id));
	}
	/// The closest hit along origin → origin + translation: { shape, point, normal, fraction } or null.
	castRayClosest(origin, translation) {
		if (this.tb.c.Web_World_CastRayClosest(this.id, origin[0], origin[1], translation[0], translation[1]) === 0) return null;
		const id = this.tb.ids(this.tb.scratch, 1)[0];
		const v = this.tb.floats(this.tb.scratch + 8, 5);
		return { shape: new Shape(this, id), point: [v[0], v[1]], normal: [v[2], v[3]], fraction: v[4] };
	}

	/// The last step's contact events: { begin: [{ shapeA, shapeB }], end: […], hit: [{ shapeA,
	/// shapeB, point, normal, approachSpeed }] } (shapes enable them with contactEvents / hitEvents).
	getContactEvents() {
		const read = (kind) => {
			const count = this.tb.c.Web_World_GetContactEvents(this.id, kind);
			const stride = kind === 2 ? 40 : 16;
			const events = [];
			for (let i = 0; i < count; ++i) {
				const ids = this.tb.ids(this.tb.scratch + i * stride, 2);
				const event = { shapeA: new Shape(this, ids[0]), shapeB: new Shape(this, ids[1]) };
				if (kind === 2) {
					const v = this.tb.floats(this.tb.scratch + i * stride + 16, 5);
					Object.assign(event, { point: [v[0], v[1]], normal: [v[2], v[3]], approachSpeed: v[4] });
				}
				events.push(event);
			}
			return events;
		};
		return { begin: read(0), end: read(1), hit: read(2) };
	}

	/// tbWorld_Draw into the debug-draw stream: calls draw.polygon(points, color),
	/// solidPolygon(points, radius, color), circle(center, radius, color), solidCircle(center,
	/// radius, axis, color), solidCapsule(p1, p2, radius, color), line(p1, p2, color),
	/// transform(p, [cos, sin]), point(p, size, color), string(p, text, color), bounds(lower,
	/// upper, color) for what overlaps view ([[lowerX, lowerY], [upperX, upperY]]); colours are
	/// 0xRRGGBB numbers; flags from `drawFlags` (default: shapes and joints). Missing callbacks skip.
	draw(draw, view, flags = drawFlags.shapes | drawFlags.joints) {
		const count = this.tb.c.Web_World_Draw(this.id, flags, view[0][0], view[0][1], view[1][0], view[1][1]);
		if (count < 0) throw new Error('debug draw: out of memory');
		const s = this.tb.floats(this.tb.c.Web_DrawStream(), count);
		const points = (at, n) => { const list = []; for (let k = 0; k < n; ++k) list.push([s[at + 2 * k], s[at + 2 * k + 1]]); return list; };
		const call = (name, ...args) => { if (draw[name]) draw[name](...args); };
		for (let i = 0; i < count;) {
			const op = s[i], color = s[i + 1];
			switch (op) {
			case 1: call('polygon', points(i + 3, s[i + 2]), color); i += 3 + 2 * s[i + 2]; break;
			case 2: call('solidPolygon', points(i + 4, s[i + 2]), s[i + 3], color); i += 4 + 2 * s[i + 2]; break;
			case 3: call('circle', [s[i + 2], s[i + 3]], s[i + 4], color); i += 5; break;
			case 4: call('solidCircle', [s[i + 2], s[i + 3]], s[i + 4], [s[i + 5], s[i + 6]], color); i += 7; break;
			case 5: call('solidCapsule', [s[i + 2], s[i + 3]], [s[i + 4], s[i + 5]], s[i + 6], color); i += 7; break;
			case 6: call('line', [s[i + 2], s[i + 3]], [s[i + 4], s[i + 5]], color); i += 6; break;
			case 7: call('transform', [s[i + 1], s[i + 2]], [s[i + 3], s[i + 4]]); i += 5; break;
			case 8: call('point', [s[i + 2], s[i + 3]], s[i + 4], color); i += 5; break;
			case 9: {
				const n = s[i + 4];
				call('string', [s[i + 2], s[i + 3]], String.fromCharCode(...s.subarray(i + 5, i + 5 + n)), color);
				i += 5 + n;
				break;
			}
			case 10: call('bounds', [s[i + 2], s[i + 3]], [s[i + 4], s[i + 5]], color); i += 6; break;
			default: throw new Error(`debug draw: unknown primitive ${op} at ${i}`);
			}
		}
	}
}

export class Body {
	constructor(world, id) {
		this.world = world;
		this.tb = world.tb;
		this.id = id;
	}

	destroy() { this.tb.c.Web_DestroyBody(this.id); }
	isValid() { return this.tb.c.Web_Body_IsValid(this.id) !== 0; }
	getType() { return Object.keys(bodyTypes)[this.tb.c.Web_Body_GetType(this.id)]; }
	state() { this.tb.c.Web_Body_GetState(this.id); return this.tb.floats(this.tb.scratch, 10); }
	getPosition() { const v = this.state(); return [v[0], v[1]]; }
	getAngle() { return this.state()[2]; }
	getLinearVelocity() { const v = this.state(); return [v[3], v[4]]; }
	getAngularVelocity() { return this.state()[5]; }
	getMass() { return this.state()[6]; }
	getWorldCenter() { const v = this.state(); return [v[7], v[8]]; }
	getRotationalInertia() { return this.state()[9]; }
	setTransform(position, angle) { return this.tb.c.Web_Body_SetTransform(this.id, position[0], position[1], angle) !== 0; }
	setVelocity(linear, angular = 0) { return this.tb.c.Web_Body_SetVelocity(this.id, linear[0], linear[1], angular) !== 0; }
	applyLinearImpulse(impulse, point, wake = true) {
		return this.tb.c.Web_Body_ApplyLinearImpulse(this.id, impulse[0], impulse[1], point[0], point[1], wake ? 1 : 0) !== 0;
	}
	applyForceToCenter(force, wake = true) { return this.tb.c.Web_Body_ApplyForceToCenter(this.id, force[0], force[1], wake ? 1 : 0) !== 0; }
	setAwake(awake) { this.tb.c.Web_Body_SetAwake(this.id, awake ? 1 : 0); }

	// Shapes. Material options m: density (1), friction (0.6), restitution (0), isSensor,
	// contactEvents, hitEvents, sensorEvents. Each returns a Shape, or null when refused (the
	// library's error hook says why).

	createCircleShape(center, radius, m = {}) {
		return this.shape(this.tb.c.Web_CreateCircleShape(this.id, center[0], center[1], radius, ...material(m)));
	}
	createCapsuleShape(p1, p2, radius, m = {}) {
		return this.shape(this.tb.c.Web_CreateCapsuleShape(this.id, p1[0], p1[1], p2[0], p2[1], radius, ...material(m)));
	}
	createSegmentShape(p1, p2, m = {}) {
		return this.shape(this.tb.c.Web_CreateSegmentShape(this.id, p1[0], p1[1], p2[0], p2[1], ...material(m)));
	}
	/// A box of half extents, centred at m.center ([0, 0]) and turned by m.angle (0).
	createBoxShape(halfWidth, halfHeight, m = {}) {
		const c = m.center || [0, 0];
		return this.shape(this.tb.c.Web_CreateBoxShape(this.id, halfWidth, halfHeight, c[0], c[1], m.angle || 0, ...material(m)));
	}
	/// The convex hull of the points ([[x, y], …], 3 to 8), rounded by m.radius (0).
	createPolygonShape(points, m = {}) {
		const out = this.tb.floats(this.tb.scratch, 2 * points.length);
		points.forEach((p, i) => { out[2 * i] = p[0]; out[2 * i + 1] = p[1]; });
		return this.shape(this.tb.c.Web_CreatePolygonShape(this.id, points.length, m.radius || 0, ...material(m)));
	}
	shape(id) { return id !== 0n ? new Shape(this.world, id) : null; }
}

function material(m) {
	const flags = (m.isSensor ? 1 : 0) | (m.contactEvents ? 2 : 0) | (m.hitEvents ? 4 : 0) | (m.sensorEvents ? 8 : 0);
	return [m.density ?? 1, m.friction ?? 0.6, m.restitution || 0, flags];
}

export class Shape {
	constructor(world, id) {
		this.world = world;
		this.id = id;
	}
	destroy() { this.world.tb.c.Web_DestroyShape(this.id); }
	getBody() { return new Body(this.world, this.world.tb.c.Web_Shape_GetBody(this.id)); }
}

export class Joint {
	constructor(world, id) {
		this.world = world;
		this.id = id;
	}
	destroy() { this.world.tb.c.Web_DestroyJoint(this.id); }
	isValid() { return this.world.tb.c.Web_Joint_IsValid(this.id) !== 0; }
	/// Moves frame A's origin to a world point (a motor joint's target) and wakes body B.
	setTargetA(point) { return this.world.tb.c.Web_Joint_SetTargetA(this.id, point[0], point[1]) !== 0; }
}

/// A catalogue scene built into a world (Tumble.loadScene): steps as `tumble run` steps it.
export class SceneRun {
	constructor(tb, pointer, name) {
		this.tb = tb;
		this.pointer = pointer;
		this.name = name;
		this.world = new World(tb, tb.c.Web_Scene_GetWorld(pointer));
	}
	destroy() { this.tb.c.Web_Scene_Destroy(this.pointer); this.pointer = 0; }
	step() { return this.tb.c.Web_Scene_Step(this.pointer) !== 0; }
	/// { timeStep, subSteps, suggestedSteps, stepIndex }
	settings() {
		this.tb.c.Web_Scene_GetSettings(this.pointer);
		const ints = this.tb.ints(this.tb.scratch + 4, 3);
		return { timeStep: this.tb.floats(this.tb.scratch, 1)[0], subSteps: ints[0], suggestedSteps: ints[1], stepIndex: ints[2] };
	}
	/// What `tumble run` prints: largest penetration (m), kinetic energy (J), awake bodies.
	readouts() {
		this.tb.c.Web_Scene_GetReadouts(this.pointer);
		const v = this.tb.floats(this.tb.scratch, 2);
		return { largestPenetration: v[0], kineticEnergy: v[1], awakeBodies: this.tb.ints(this.tb.scratch + 8, 1)[0] };
	}
	/// The box that frames the scene's moving bodies: [[lowerX, lowerY], [upperX, upperY]].
	bounds() {
		this.tb.c.Web_Scene_GetBounds(this.pointer);
		const v = this.tb.floats(this.tb.scratch, 4);
		return [[v[0], v[1]], [v[2], v[3]]];
	}
}
