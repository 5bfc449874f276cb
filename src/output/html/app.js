// The report's 3D view: the room in millimetres with z up, one group of
// objects per task, a list of tasks to click through, and the text report's
// facts of the chosen task beside the view.
import * as THREE from "three";
import { OrbitControls } from "three/orbit";

const COLOURS = {
  ok: 0x2e9e4f,
  not: 0xd64545,
  idle: 0x8a93a3,
  sight: 0x2b6cd6,
  strained: 0xff2d95,
  box: 0xd8c8a8,
  mesh: 0xc9c1b1,
  blocked: 0xff5a36,
  floor: 0xeceff3,
  surface: 0x4a7bd0,
  door: 0x6b4fbb,
  through: 0xc463c9,
  wall: 0xe3e6eb,
};

// How far short a map cell fell, as a colour: green where reached, then
// yellow to red as the shortfall grows to 300 mm and beyond; purple (a
// negative value) where there only through something.
const RAMP_MM = 300;
function shortColour(shortMm) {
  const c = new THREE.Color();
  if (shortMm < 0) return c.setHex(COLOURS.through);
  if (shortMm === 0) return c.setHex(COLOURS.ok);
  const t = Math.min(shortMm / RAMP_MM, 1);
  return c.setHex(0xe8d44d).lerp(new THREE.Color(COLOURS.not), t);
}

// A population's share of a point, as a colour: the first band (of the
// report's, which the SVG maps use too) whose least share it reaches.
function shareColour(share, bands) {
  const band = bands.find(([least]) => share >= least) || bands[bands.length - 1];
  return new THREE.Color(band[1]);
}

function v3(a) {
  return new THREE.Vector3(a[0], a[1], a[2]);
}

function lambert(colour, opacity = 1) {
  return new THREE.MeshLambertMaterial({
    color: colour,
    transparent: opacity < 1,
    opacity,
    side: THREE.DoubleSide,
  });
}

// A capsule from a to b of radius r.
function capsule(a, b, r, material) {
  const from = v3(a), to = v3(b);
  const axis = to.clone().sub(from);
  const length = axis.length();
  const mesh = new THREE.Mesh(new THREE.CapsuleGeometry(Math.max(r, 1), length, 6, 12), material);
  mesh.position.copy(from).add(to).multiplyScalar(0.5);
  if (length > 1e-9) {
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis.normalize());
  }
  return mesh;
}

function sphere(at, r, colour) {
  const mesh = new THREE.Mesh(new THREE.SphereGeometry(r, 20, 14), lambert(colour));
  mesh.position.copy(v3(at));
  return mesh;
}

// A marker seen through whatever stands in front of it.
function marker(at, r, colour) {
  const mesh = sphere(at, r, colour);
  // Transparent (though opaque) so it is drawn after the see-through
  // furniture, last of all.
  mesh.material = new THREE.MeshBasicMaterial({
    color: colour,
    depthTest: false,
    transparent: true,
    opacity: 1,
  });
  mesh.renderOrder = 10;
  return mesh;
}

function line(points, colour, dashed) {
  const geometry = new THREE.BufferGeometry().setFromPoints(points.map(v3));
  const material = dashed
    ? new THREE.LineDashedMaterial({ color: colour, dashSize: 40, gapSize: 25 })
    : new THREE.LineBasicMaterial({ color: colour });
  const l = new THREE.Line(geometry, material);
  if (dashed) l.computeLineDistances();
  return l;
}

// The room: floor, walls as edges, boxes, meshes, surfaces and targets.
function buildRoom(room) {
  const group = new THREE.Group();
  const [x, y, z] = room.size;
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(x, y), lambert(COLOURS.floor));
  floor.position.set(x / 2, y / 2, -0.5);
  group.add(floor);
  const grid = new THREE.GridHelper(Math.max(x, y), Math.ceil(Math.max(x, y) / 500), 0xc3c8d2, 0xd7dbe2);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(Math.max(x, y) / 2, Math.max(x, y) / 2, 0);
  grid.material.clippingPlanes = [];
  group.add(grid);
  const walls = new THREE.LineSegments(
    new THREE.EdgesGeometry(new THREE.BoxGeometry(x, y, z)),
    new THREE.LineBasicMaterial({ color: 0x9aa3b2 })
  );
  walls.position.set(x / 2, y / 2, z / 2);
  group.add(walls);
  const sides = buildWalls(room);
  sides.forEach((side) => group.add(side.group));
  const obstacles = new Map();
  for (const b of room.boxes) {
    const pivot = new THREE.Group();
    pivot.position.copy(v3(b.corner));
    pivot.rotation.z = THREE.MathUtils.degToRad(b.yaw_deg);
    const geometry = new THREE.BoxGeometry(b.size[0], b.size[1], b.size[2]);
    const mesh = new THREE.Mesh(geometry, lambert(COLOURS.box, 0.6));
    mesh.position.set(b.size[0] / 2, b.size[1] / 2, b.size[2] / 2);
    const edges = new THREE.LineSegments(
      new THREE.EdgesGeometry(geometry),
      new THREE.LineBasicMaterial({ color: 0x7a6a50 })
    );
    edges.position.copy(mesh.position);
    pivot.add(mesh, edges);
    mesh.userData.name = b.name;
    group.add(pivot);
    obstacles.set(b.name, mesh);
  }
  for (const m of room.meshes) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.Float32BufferAttribute(m.positions, 3));
    geometry.setIndex(m.indices);
    geometry.computeVertexNormals();
    const mesh = new THREE.Mesh(geometry, lambert(COLOURS.mesh, 0.6));
    mesh.userData.name = m.name;
    group.add(mesh);
    obstacles.set(m.name, mesh);
  }
  for (const s of room.surfaces) {
    const c = v3(s.corner), u = v3(s.u), v = v3(s.v);
    const corners = [c, c.clone().add(u), c.clone().add(u).add(v), c.clone().add(v), c];
    group.add(line(corners.map((p) => [p.x, p.y, p.z]), COLOURS.surface, true));
  }
  // Doors: their openings on the floor, a thick band in the wall's line.
  for (const d of room.doors || []) {
    const from = new THREE.Vector3(d.from[0], d.from[1], 0);
    const to = new THREE.Vector3(d.to[0], d.to[1], 0);
    const length = from.distanceTo(to);
    const band = new THREE.Mesh(new THREE.BoxGeometry(length, 60, 20), lambert(COLOURS.door));
    band.position.copy(from).add(to).multiplyScalar(0.5);
    band.rotation.z = Math.atan2(to.y - from.y, to.x - from.x);
    band.userData.name = d.name;
    group.add(band);
  }
  const targets = new Map();
  for (const t of room.targets) {
    const mesh = marker(t.at, 28, COLOURS.idle);
    mesh.userData.name = t.name;
    group.add(mesh);
    targets.set(t.name, mesh);
  }
  return { group, obstacles, targets, sides };
}

// A door's opening is this high (the ADA's 80 in) unless the room is lower.
const DOOR_HEIGHT_MM = 2030;

// The room's four walls, each a group of panels round its doors'
// openings, with a point on it and the normal into the room: a wall
// between the camera and the room is hidden (cut away) as it turns.
function buildWalls(room) {
  const [x, y, z] = room.size;
  const corners = [[0, 0], [x, 0], [x, y], [0, y]];
  const material = new THREE.MeshLambertMaterial({
    color: COLOURS.wall,
    side: THREE.DoubleSide,
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  const up = new THREE.Vector3(0, 0, 1);
  return corners.map((c, k) => {
    const p0 = new THREE.Vector3(c[0], c[1], 0);
    const next = corners[(k + 1) % 4];
    const p1 = new THREE.Vector3(next[0], next[1], 0);
    const length = p0.distanceTo(p1);
    const along = p1.clone().sub(p0).normalize();
    const inward = up.clone().cross(along);
    // The doors in this wall, as spans along it.
    const openings = (room.doors || [])
      .map((d) => [new THREE.Vector3(d.from[0], d.from[1], 0), new THREE.Vector3(d.to[0], d.to[1], 0)])
      .filter(([a, b]) => [a, b].every((q) => Math.abs(q.clone().sub(p0).dot(inward)) < 1))
      .map(([a, b]) => [a.clone().sub(p0).dot(along), b.clone().sub(p0).dot(along)].sort((m, n) => m - n));
    const doorTop = Math.min(DOOR_HEIGHT_MM, z);
    const panels = [];
    let s = 0;
    for (const [from, to] of openings.sort((m, n) => m[0] - n[0])) {
      if (from > s) panels.push([s, from, 0, z]);
      if (doorTop < z) panels.push([from, to, doorTop, z]);
      s = Math.max(s, to);
    }
    if (s < length) panels.push([s, length, 0, z]);
    const group = new THREE.Group();
    const basis = new THREE.Matrix4().makeBasis(along, up, along.clone().cross(up));
    for (const [s0, s1, h0, h1] of panels) {
      const panel = new THREE.Mesh(new THREE.PlaneGeometry(s1 - s0, h1 - h0), material);
      panel.applyMatrix4(basis);
      panel.position.copy(p0).addScaledVector(along, (s0 + s1) / 2).setZ((h0 + h1) / 2);
      group.add(panel);
    }
    group.userData.wall = k;
    return { group, point: p0, inward };
  });
}

// One task's objects: the person, the line of sight, the map's cells and
// the joints at a limit.
function buildTask(task, data) {
  const group = new THREE.Group();
  for (const s of task.solids) {
    const material = lambert(new THREE.Color(s.color), s.opacity);
    if (s.kind === "capsule") {
      group.add(capsule(s.a, s.b, s.r, material));
    } else {
      const mesh = new THREE.Mesh(
        new THREE.BoxGeometry(2 * s.half[0], 2 * s.half[1], 2 * s.half[2]),
        material
      );
      mesh.position.copy(v3(s.centre));
      mesh.rotation.z = THREE.MathUtils.degToRad(s.yaw_deg);
      group.add(mesh);
    }
  }
  if (task.reached && task.target) {
    group.add(line([task.reached, task.target], task.ok ? COLOURS.ok : COLOURS.not, true));
  }
  if (task.sight) {
    const s = task.sight;
    group.add(line([s.eyes, s.target], s.ok ? COLOURS.sight : COLOURS.not, false));
    group.add(sphere(s.eyes, 12, COLOURS.sight));
  }
  // An advice: its target where it serves the most (its boxes are among
  // the solids, see-through green).
  if (task.advised) {
    const point = marker(task.advised.at, 34, COLOURS.ok);
    point.userData.name = task.advised.name;
    group.add(point);
  }
  for (const j of task.strained) {
    group.add(marker(j.at, 30, COLOURS.strained));
  }
  // Where the room has doors: the edge of the floor the base can get to
  // from one, at the heading it was placed at.
  for (const ring of task.routes || []) {
    group.add(line(ring.map(([x, y]) => [x, y, 2]), COLOURS.door, true));
  }
  // A standard's marks: clear floor spaces and turning spaces on the
  // floor, elements as markers, green where their rule holds, red not.
  for (const m of task.marks || []) {
    const colour = m.ok ? COLOURS.ok : COLOURS.not;
    if (m.kind === "point") {
      const point = marker(m.at, 34, colour);
      point.userData.name = m.label;
      group.add(point);
      continue;
    }
    const shape = new THREE.Shape();
    if (m.kind === "circle") {
      shape.absarc(m.centre[0], m.centre[1], m.radius, 0, 2 * Math.PI, false);
    } else {
      m.points.forEach(([x, y], k) => (k === 0 ? shape.moveTo(x, y) : shape.lineTo(x, y)));
    }
    // Faint fills, so that spaces laid over each other stay apart by
    // their outlines; a failing space drawn over those that hold.
    const area = new THREE.Mesh(
      new THREE.ShapeGeometry(shape, 48),
      new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: m.ok ? 0.14 : 0.24, side: THREE.DoubleSide, depthWrite: false })
    );
    area.position.z = m.ok ? 3 : 5;
    area.renderOrder = m.ok ? 1 : 2;
    area.userData.name = m.label;
    group.add(area);
    const outline = shape.getPoints(48).map((p) => new THREE.Vector3(p.x, p.y, m.ok ? 4 : 6));
    const edge = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(outline),
      m.ok
        ? new THREE.LineBasicMaterial({ color: colour })
        : new THREE.LineDashedMaterial({ color: colour, dashSize: 60, gapSize: 30 })
    );
    if (!m.ok) edge.computeLineDistances();
    edge.renderOrder = m.ok ? 1 : 2;
    group.add(edge);
  }
  if (task.cells) {
    const c = task.cells;
    const u = v3(c.u).normalize(), v = v3(c.v).normalize();
    const normal = u.clone().cross(v).normalize();
    const size = 0.9 * c.step;
    const cell = new THREE.PlaneGeometry(size, size);
    const instances = new THREE.InstancedMesh(
      cell,
      new THREE.MeshBasicMaterial({ side: THREE.DoubleSide }),
      c.points.length
    );
    const basis = new THREE.Matrix4().makeBasis(u, v, normal);
    const m = new THREE.Matrix4();
    c.points.forEach((p, k) => {
      m.copy(basis).setPosition(p[0] + normal.x * 3, p[1] + normal.y * 3, p[2] + normal.z * 3);
      instances.setMatrixAt(k, m);
      const colour = c.of === "gaze"
        ? new THREE.Color(p[3] > 0 ? COLOURS.not : COLOURS.sight)
        : c.of === "share"
          ? shareColour(p[3], data.share_bands)
          : shortColour(p[3]);
      instances.setColorAt(k, colour);
    });
    group.add(instances);
  }
  return group;
}

function legend(data) {
  const rows = [
    ["#2e9e4f", "reached / seen"],
    ["#d64545", "NOT reached / seen"],
    ["#e8b48a", "the person"],
    ["#7d8590", "the base"],
    ["#ff2d95", "a joint at its limit"],
    ["#ff5a36", "what blocked it"],
    ["#2b6cd6", "line of sight"],
    ["#e3e6eb", "the room's walls (cut away where they face you)"],
  ];
  if (data.rooms.some((r) => (r.doors || []).length)) {
    rows.push(["#6b4fbb", "a door; dashed: where the base can get to from one"]);
  }
  if (data.tasks.some((t) => t.advised)) {
    rows.push(["#2e9e4f", "an advice: the element where it serves the most (see-through)"]);
  }
  if (data.tasks.some((t) => (t.marks || []).length)) {
    rows.push(["#2e9e4f", "a standard's rule holds (floor space, element)"]);
    rows.push(["#d64545", "a standard's rule fails (floor space: dashed outline)"]);
  }
  let html = rows
    .map(([c, t]) => `<div class="row"><span class="swatch" style="background:${c}"></span>${t}</div>`)
    .join("");
  if (data.tasks.some((t) => t.cells && t.cells.of !== "share")) {
    html += `<div class="row"><span class="swatch" style="background:#2b6cd6"></span>gaze map: seen</div>`;
    html += `<div class="row">reach map: reached &rarr; short by</div><div class="row"><span class="ramp"></span></div>` +
      `<div class="row" style="justify-content:space-between;width:140px"><span>0</span><span>${RAMP_MM / 2}</span><span>&ge;${RAMP_MM} mm short</span></div>`;
  }
  if (data.tasks.some((t) => t.cells && t.cells.of !== "share" && t.cells.points.some((p) => p[3] < 0))) {
    html += `<div class="row"><span class="swatch" style="background:#c463c9"></span>reach map: there only through something</div>`;
  }
  if (data.tasks.some((t) => t.cells && t.cells.of === "share")) {
    html += `<div class="row">population map: share who reach</div>` +
      data.share_bands
        .map(([, c, t]) => `<div class="row"><span class="swatch" style="background:${c}"></span>${t}</div>`)
        .join("");
  }
  document.getElementById("legend-body").innerHTML = html;
}

// "; expectations: 6 met, 1 NOT met", or nothing.
function expectationsSummary(data) {
  const all = data.expectations;
  if (all.length === 0) return "";
  const met = all.filter((e) => e.met).length;
  return `; expectations: ${met} met, ${all.length - met} NOT met`;
}

// A dot in the colour of a verdict: met or reached, or not; grey where
// nothing was looked for (the work limit stopped the run before it).
function verdictDot(ok, notEvaluated = false) {
  const dot = document.createElement("span");
  dot.className = "dot";
  dot.style.background = notEvaluated ? "#9a9a9a" : ok ? "#2e9e4f" : "#d64545";
  return dot;
}

// Each expectation, met or not, and why.
function listExpectations(expectations) {
  const list = document.getElementById("expectations");
  for (const e of expectations) {
    const item = document.createElement("li");
    const dot = verdictDot(e.met);
    const because = document.createElement("span");
    because.className = "because";
    because.textContent = `${e.met ? "met" : "NOT met"}: ${e.because} (${e.at})`;
    item.append(dot, document.createTextNode(`expect ${e.expect}`), because);
    list.append(item);
  }
}

export function start(settings, data) {
  const view = document.getElementById("view");
  const status = document.getElementById("status");
  const selftest = new URLSearchParams(location.search).has("selftest");
  document.getElementById("file").textContent = data.title;
  const ok = data.tasks.filter((t) => t.ok).length;
  const simplified = data.rooms.flatMap((r) => r.meshes)
    .filter((m) => m.simplified_from)
    .map((m) => `; ${m.name} drawn with ${m.indices.length / 3} of its ${m.simplified_from} triangles (answers use them all)`);
  const unrun = data.tasks.filter((t) => t.not_evaluated).length;
  const unrunWords = unrun ? `, ${unrun} not evaluated (work limit)` : "";
  document.getElementById("summary").textContent =
    `${data.tasks.length} tasks, ${ok} ok` + unrunWords + simplified.join("") + expectationsSummary(data);
  listExpectations(data.expectations);

  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: selftest });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xffffff);
  view.prepend(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(-0.4, -0.8, 1.2);
  scene.add(sun);
  // Two cameras: in perspective (turned with the mouse), and the plan,
  // straight down (panned and zoomed only); each with its own controls.
  const camera = new THREE.PerspectiveCamera(45, 1, 10, 200000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;
  const planCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 10, 200000);
  planCamera.up.set(0, 1, 0);
  const planControls = new OrbitControls(planCamera, renderer.domElement);
  planControls.enableRotate = false;
  planControls.screenSpacePanning = true;
  planControls.enabled = false;

  const rooms = data.rooms.map(buildRoom);
  rooms.forEach((r) => scene.add(r.group));
  // Each task's objects are built the first time it is shown.
  const groups = data.tasks.map(() => null);
  function group(k) {
    if (!groups[k]) {
      groups[k] = buildTask(data.tasks[k], data);
      scene.add(groups[k]);
    }
    return groups[k];
  }
  legend(data);

  const list = document.getElementById("tasks");
  const buttons = data.tasks.map((t, k) => {
    const item = document.createElement("li");
    const button = document.createElement("button");
    const dot = verdictDot(t.ok, t.not_evaluated);
    const verdict = document.createElement("span");
    verdict.className = "verdict";
    verdict.textContent = t.verdict;
    button.append(dot, document.createTextNode(t.label), verdict);
    button.addEventListener("click", () => select(k, "task"));
    item.append(button);
    list.append(item);
    return button;
  });

  // Over the person's shoulder at what the task asked about; a map from
  // above its surface.
  function frameTask(task) {
    const [x, y] = data.rooms[task.room].size;
    const centre = new THREE.Vector3(x / 2, y / 2, 700);
    let at, from;
    if (task.cells) {
      const p = task.cells.points;
      at = p.reduce((s, q) => s.add(v3(q)), new THREE.Vector3()).divideScalar(Math.max(p.length, 1));
      from = at.clone().add(v3(task.cells.u).cross(v3(task.cells.v)).normalize().multiplyScalar(2200));
      from.add(centre.clone().sub(at).setZ(0).normalize().multiplyScalar(1400));
    } else if (task.target && task.base) {
      const base = v3(task.base), target = v3(task.target);
      at = base.clone().lerp(target, 0.55);
      at.z = Math.max((base.z + target.z) / 2, 600);
      const back = backOf(task);
      const side = new THREE.Vector3(-back.y, back.x, 0);
      from = at.clone().add(back.multiplyScalar(1900)).add(side.multiplyScalar(900));
      from.z = at.z + 1500;
    } else {
      return frameRoom(data.rooms[task.room], task);
    }
    controls.target.copy(at);
    camera.position.copy(from);
    controls.update();
  }

  // The way from the target back to the person, level: where the camera
  // stands to look at the task.
  function backOf(task) {
    const back = task && task.target && task.base
      ? v3(task.base).sub(v3(task.target)).setZ(0)
      : new THREE.Vector3(-0.45, -0.75, 0);
    if (back.lengthSq() < 1) back.set(-1, -1, 0);
    return back.normalize();
  }

  // The whole room in view, from above behind the person (or from a
  // corner): its bounding sphere fitted within the narrower field.
  function frameRoom(room, task) {
    const [x, y, z] = room.size;
    const centre = new THREE.Vector3(x / 2, y / 2, z / 3);
    const radius = 0.5 * Math.hypot(x, y, z);
    const vertical = THREE.MathUtils.degToRad(camera.fov);
    const horizontal = 2 * Math.atan(Math.tan(vertical / 2) * camera.aspect);
    // A little farther than the sphere's fit, for the hint along the
    // foot of the view.
    const distance = 1.06 * radius / Math.sin(Math.min(vertical, horizontal) / 2);
    const from = backOf(task).add(new THREE.Vector3(0, 0, 1.1)).normalize();
    controls.target.copy(centre);
    camera.position.copy(centre).addScaledVector(from, distance);
    controls.update();
  }

  // The plan: straight down on the room, all of it in view.
  function framePlan(room) {
    const [x, y, z] = room.size;
    const aspect = camera.aspect;
    const half = 0.55 * Math.max(y, x / aspect);
    Object.assign(planCamera, { left: -half * aspect, right: half * aspect, top: half, bottom: -half, zoom: 1 });
    planCamera.position.set(x / 2, y / 2, z + 5000);
    planControls.target.set(x / 2, y / 2, 0);
    planCamera.updateProjectionMatrix();
    planControls.update();
  }

  // What is shown: "task" (close on the task), "room" (the whole room) or
  // "plan"; and which task.
  let current = -1;
  let mode = "room";
  const viewButtons = toolbar((m) => show(m));

  function select(k, how = mode) {
    if (k < 0 || k >= data.tasks.length) return;
    current = k;
    const task = data.tasks[k];
    groups.forEach((g) => g && (g.visible = false));
    group(k).visible = true;
    rooms.forEach((r, i) => {
      r.group.visible = i === task.room;
      for (const mesh of r.targets.values()) mesh.material.color.setHex(COLOURS.idle);
      for (const mesh of r.obstacles.values()) {
        mesh.material.emissive.setHex(0x000000);
      }
    });
    const room = rooms[task.room];
    const subject = task.label.split(" ")[1];
    const target = room.targets.get(subject);
    // A task not evaluated leaves its target as it is: nothing was found.
    // An advice leaves it as declared: its answer is the green element
    // where it serves the most, and the plot.
    if (target && !task.not_evaluated && !task.plot) target.material.color.setHex(task.ok ? COLOURS.ok : COLOURS.not);
    const blocker = task.blocked_by && room.obstacles.get(task.blocked_by);
    if (blocker) blocker.material.emissive.setHex(COLOURS.blocked);
    buttons.forEach((b, i) => b.classList.toggle("selected", i === k));
    buttons[k].scrollIntoView({ block: "nearest" });
    const strained = task.strained.map((j) => j.name).join(", ");
    const facts = document.getElementById("facts");
    facts.textContent = task.details + (strained ? `\n  at a limit (pink): ${strained}` : "");
    // An advice's plot over the view: SVG the report made, its words
    // escaped there.
    const plotBox = document.getElementById("plot-box");
    plotBox.hidden = !task.plot;
    plotBox.innerHTML = task.plot || "";
    show(how);
  }

  // The chosen task's room (the first where no task is chosen), and its
  // description (a stand-in where the scenario has no room).
  function roomIndex() {
    const task = data.tasks[current];
    return task ? task.room : 0;
  }
  function roomData() {
    return data.rooms[roomIndex()] || { size: [3000, 3000, 2500] };
  }

  // Frame the chosen task as `how` says, and keep it in the address.
  function show(how) {
    mode = how;
    const task = data.tasks[current];
    const room = roomData();
    controls.enabled = mode !== "plan";
    planControls.enabled = mode === "plan";
    if (mode === "plan") framePlan(room);
    else if (mode === "task" && task) frameTask(task);
    else frameRoom(room, task);
    viewButtons.forEach((b) => b.classList.toggle("selected", b.dataset.view === mode));
    if (current >= 0) {
      history.replaceState(null, "", `#task=${current}${mode === "task" ? "" : `&view=${mode}`}`);
    }
    render();
  }

  function resize() {
    const w = view.clientWidth, h = view.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    if (mode === "plan") framePlan(roomData());
    render();
  }

  // Walls between the camera and the room's inside are cut away; in the
  // plan every wall is seen edge on.
  function cutAway() {
    const eye = mode === "plan" ? null : camera.position;
    for (const r of rooms) {
      for (const side of r.sides) {
        side.group.visible = !eye || eye.clone().sub(side.point).dot(side.inward) >= 0;
      }
    }
  }

  function render() {
    cutAway();
    renderer.render(scene, mode === "plan" ? planCamera : camera);
  }

  controls.addEventListener("change", render);
  planControls.addEventListener("change", render);
  // What is under the pointer, named: a target, a box, a mesh, a door, a
  // standard's floor space or element with what its rule measured.
  const tip = document.getElementById("tip");
  const ray = new THREE.Raycaster();
  renderer.domElement.addEventListener("pointermove", (e) => {
    const box = renderer.domElement.getBoundingClientRect();
    const at = new THREE.Vector2(
      ((e.clientX - box.left) / box.width) * 2 - 1,
      -((e.clientY - box.top) / box.height) * 2 + 1
    );
    ray.setFromCamera(at, mode === "plan" ? planCamera : camera);
    const shown = [groups[current], ...rooms.map((r) => r.group)].filter((g) => g && g.visible);
    const hit = ray.intersectObjects(shown, true).find((h) => h.object.userData.name);
    tip.hidden = !hit;
    if (hit) {
      tip.textContent = hit.object.userData.name;
      tip.style.left = `${e.clientX - box.left + 14}px`;
      tip.style.top = `${e.clientY - box.top + 14}px`;
    }
  });
  renderer.domElement.addEventListener("pointerleave", () => (tip.hidden = true));
  window.addEventListener("resize", resize);
  window.addEventListener("keydown", (e) => {
    const n = Number.parseInt(e.key, 10);
    if (n >= 1 && n <= 9) select(n - 1, "task");
    const views = { r: "room", p: "plan", t: "task" };
    if (views[e.key]) show(views[e.key]);
    if (e.key === "l") document.getElementById("legend-box").toggleAttribute("open");
  });
  window.addEventListener("hashchange", () => {
    const asked = fromHash();
    select(asked.task ?? 0, asked.view ?? "task");
  });

  resize();
  // `#task=N` (from 0, in the order of the list) opens on that task, close
  // on it; `&view=room` or `&view=plan` as the buttons say. Without it the
  // page opens on the whole room.
  const asked = fromHash();
  if (data.tasks.length > 0) {
    const task = Math.min(asked.task ?? 0, data.tasks.length - 1);
    select(task, asked.view ?? (asked.task === undefined ? "room" : "task"));
  } else {
    show(asked.view === "plan" ? "plan" : "room");
  }
  status.textContent = "";
  document.body.dataset.readyMs = String(Math.round(performance.now()));
  document.body.dataset.ready = "1";

  if (settings.live) poll(settings, selftest);
  if (selftest) {
    // The pointer over the chosen task's room's first target: its name
    // should show.
    const hover = () => {
      const room = rooms[roomIndex()];
      const target = room && room.targets.values().next().value;
      if (!target) return "";
      const at = target.position.clone().project(mode === "plan" ? planCamera : camera);
      const box = renderer.domElement.getBoundingClientRect();
      renderer.domElement.dispatchEvent(new PointerEvent("pointermove", {
        clientX: box.left + ((at.x + 1) / 2) * box.width,
        clientY: box.top + ((1 - at.y) / 2) * box.height,
      }));
      return tip.hidden ? "" : tip.textContent;
    };
    runSelftest(renderer, buttons, render, () => ({
      tip: hover(),
      selected: current,
      view: mode,
      walls: rooms[roomIndex()].sides
        .map((side) => (side.group.visible ? 1 : 0)),
    }));
  }
}

// The task and view the address asks for: `#task=3&view=plan`.
function fromHash() {
  const task = /task=(\d+)/.exec(location.hash);
  const view = /view=(room|plan|task)/.exec(location.hash);
  return { task: task ? Number(task[1]) : undefined, view: view ? view[1] : undefined };
}

// The buttons over the view that choose how it is framed.
function toolbar(choose) {
  const bar = document.getElementById("toolbar");
  return [["task", "Task", "t"], ["room", "Whole room", "r"], ["plan", "Plan", "p"]].map(([view, words, key]) => {
    const button = document.createElement("button");
    button.textContent = words;
    button.title = `${words} (key ${key})`;
    button.dataset.view = view;
    button.addEventListener("click", () => choose(view));
    bar.append(button);
    return button;
  });
}

// Reload when `reach` writes new answers: the stamp file beside the page
// calls window.reachStamp with the stamp of what the page would now show.
function poll(settings, selftest) {
  window.reachStamp = (stamp) => {
    if (stamp === settings.stamp) return;
    if (selftest) document.body.dataset.stale = "1";
    else location.reload();
  };
  const load = () => {
    const script = document.createElement("script");
    script.src = `${settings.stampFile}?t=${Date.now()}`;
    script.onload = script.onerror = () => script.remove();
    document.head.append(script);
  };
  load();
  setInterval(load, 1000);
}

// For the browser test: the picture's pixels before and after a click on
// the second task, and how many differ.
function runSelftest(renderer, buttons, render, state) {
  const shown = state();
  const gl = renderer.getContext();
  const pixels = () => {
    render();
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const out = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return out;
  };
  const before = pixels();
  let white = 0;
  for (let i = 0; i < before.length; i += 4) {
    if (before[i] > 250 && before[i + 1] > 250 && before[i + 2] > 250) white++;
  }
  let changed = 0;
  if (buttons.length > 1) {
    buttons[1].click();
    const after = pixels();
    for (let i = 0; i < after.length; i += 4) {
      if (Math.abs(after[i] - before[i]) + Math.abs(after[i + 1] - before[i + 1]) +
          Math.abs(after[i + 2] - before[i + 2]) > 30) changed++;
    }
    buttons[shown.selected].click();
  }
  document.body.dataset.selftest = JSON.stringify({
    ...shown,
    tasks: buttons.length,
    pixels: before.length / 4,
    notWhite: before.length / 4 - white,
    changedByClick: changed,
  });
}
