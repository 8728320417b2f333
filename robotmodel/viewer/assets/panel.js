// Control panel: meshcat's three.js viewer plus joint sliders, over one websocket.
// Binary messages are meshcat commands; text messages are JSON for the panel.
(function () {
  "use strict";
  const STEPS = 10000;  // joint_state_publisher_gui's slider resolution
  const viewer = new MeshCat.Viewer(document.getElementById("meshcat-pane"));
  const state = {connected: false, synced: 0, renders: 0, latencies: [], config: null, positions: {},
                 timing: {}};
  window.viewer = viewer;
  window.robotmodel = state;
  const sliders = {};
  const sentAt = new Map();
  let ws = null;
  let token = 0;

  function status(text, bad) {
    const el = document.getElementById("status");
    el.textContent = text;
    el.className = bad ? "status bad" : "status";
  }

  function send(message) {
    if (ws && ws.readyState === WebSocket.OPEN) ws.send(JSON.stringify(message));
  }

  function toValue(joint, step) {
    return joint.min + (joint.max - joint.min) * step / STEPS;
  }

  function toStep(joint, value) {
    if (joint.max === joint.min) return 0;
    // Truncation, as joint_state_publisher_gui converts with int().
    return Math.trunc((value - joint.min) / (joint.max - joint.min) * STEPS);
  }

  function showValue(name, value) {
    const s = sliders[name];
    if (s) s.value.textContent = value.toFixed(3);
  }

  function applyMimics() {
    for (const m of state.config.mimics) {
      if (m.master in state.positions) {
        const v = state.positions[m.master] * m.multiplier + m.offset;
        showValue(m.joint, v);
      }
    }
  }

  function publish() {
    token += 1;
    sentAt.set(token, performance.now());
    send({type: "joints", positions: Object.assign({}, state.positions), token: token});
    applyMimics();
  }

  function setPositions(positions) {
    for (const [name, value] of Object.entries(positions)) {
      const s = sliders[name];
      if (!s) continue;
      state.positions[name] = value;
      s.input.value = toStep(s.joint, value);
      showValue(name, value);
    }
    applyMimics();
  }

  function buildPanel(config) {
    state.config = config;
    document.getElementById("robot-name").textContent = config.robot;
    document.title = config.robot + " — robotmodel view";
    const box = document.getElementById("sliders");
    box.textContent = "";
    for (const key of Object.keys(sliders)) delete sliders[key];
    const mimicOf = {};
    for (const m of config.mimics) mimicOf[m.joint] = m;
    for (const joint of config.joints) {
      const row = document.createElement("div");
      row.className = "joint";
      row.innerHTML = '<div class="head"><span class="name"></span><span class="value"></span></div>';
      row.querySelector(".name").textContent = joint.name;
      row.querySelector(".name").title = joint.name;
      const input = document.createElement("input");
      input.type = "range";
      input.min = 0;
      input.max = STEPS;
      input.step = 1;
      input.id = "joint-" + joint.name;
      input.dataset.joint = joint.name;
      input.addEventListener("input", () => {
        state.positions[joint.name] = toValue(joint, Number(input.value));
        showValue(joint.name, state.positions[joint.name]);
        publish();
      });
      row.appendChild(input);
      box.appendChild(row);
      sliders[joint.name] = {joint: joint, input: input, value: row.querySelector(".value")};
    }
    for (const m of config.mimics) {
      const row = document.createElement("div");
      row.className = "joint mimic";
      row.innerHTML = '<div class="head"><span class="name"></span><span class="value"></span></div>';
      row.querySelector(".name").textContent = m.joint;
      box.appendChild(row);
      sliders[m.joint] = {joint: null, input: null, value: row.querySelector(".value")};
    }
    const positions = {};
    for (const joint of config.joints) positions[joint.name] = joint.value;
    setPositions(positions);
    document.getElementById("joint-buttons").style.display = config.joints.length ? "" : "none";
    document.getElementById("show-collisions").checked = config.collisions;
    document.getElementById("show-frames").checked = config.frames.length > 0;
    const live = config.follow ? " · following /joint_states" : "";
    status(config.joints.length + " movable joints" + (config.publish ? " · publishing /joint_states" : "") + live);
  }

  // Draws are throttled: at most 30 a second, and never closer than one draw's own cost,
  // so batches arriving faster (a streaming /tf, a 60 Hz drag) are drawn together and the
  // page keeps at least half its time for everything else. The first batch after a pause
  // is drawn at once (leading edge), which keeps a slider's latency low.
  const MIN_PERIOD = 1000 / 30;
  let drawTimer = null;
  let lastDrawEnd = -Infinity;
  let lastDrawCost = 0;
  let drawnToken = null;
  state.renderMs = 0;

  function draw() {
    drawTimer = null;
    const start = performance.now();
    viewer.render();
    const end = performance.now();
    lastDrawCost = end - start;
    lastDrawEnd = end;
    state.renderMs += lastDrawCost;
    state.renders += 1;
    if (!state.timing.drawn) state.timing.drawn = end;
    if (drawnToken != null) {
      for (const [t, at] of sentAt) {
        if (t <= drawnToken) {
          state.latencies.push(end - at);
          sentAt.delete(t);
        }
      }
      drawnToken = null;
    }
  }

  function onSynced(message) {
    if (!state.timing.synced) state.timing.synced = performance.now();
    state.synced = message.seq;
    if (message.token != null) drawnToken = Math.max(drawnToken || 0, message.token);
    requestDraw();
  }

  function requestDraw() {
    if (drawTimer !== null) return;
    const wait = lastDrawEnd + Math.max(MIN_PERIOD, lastDrawCost) - performance.now();
    if (wait <= 0) draw();
    else drawTimer = setTimeout(draw, wait);
  }

  // The camera's target lives in OrbitControls, which meshcat's commands cannot reach (see
  // _camera.py); coordinates are three.js's. Without a position the camera moves along with
  // the target, keeping the orbit and zoom chosen in this page.
  function onCamera(message) {
    const target = new MeshCat.THREE.Vector3().fromArray(message.target);
    if (message.position) viewer.camera.position.fromArray(message.position);
    else viewer.camera.position.add(target.clone().sub(viewer.controls.target));
    viewer.controls.target.copy(target);
    state.cameraMoves = (state.cameraMoves || 0) + 1;
    if (state.synced > 0) requestDraw();
  }

  function onText(message) {
    if (message.type === "config") {
      buildPanel(message);
      if (message.camera) onCamera(message.camera);
    }
    else if (message.type === "camera") onCamera(message);
    else if (message.type === "synced") onSynced(message);
    else if (message.type === "positions") setPositions(message.positions);
    else if (message.type === "status") status(message.text, message.bad);
  }

  function connect() {
    ws = new WebSocket("ws://" + location.host + "/ws");
    ws.binaryType = "arraybuffer";
    ws.onopen = () => { state.connected = true; state.timing.open = performance.now(); };
    ws.onmessage = (event) => {
      if (typeof event.data === "string") onText(JSON.parse(event.data));
      else {
        if (!state.timing.first) state.timing.first = performance.now();
        viewer.handle_command_bytearray(new Uint8Array(event.data));
        // Draw once per batch, when its "synced" marker arrives, not on every animation
        // frame in between (a software-rendered frame of a big robot costs tens of ms).
        viewer.needs_render = false;
      }
    };
    ws.onclose = () => {
      state.connected = false;
      status("disconnected from the viewer process", true);
    };
  }

  document.getElementById("center").addEventListener("click", () => {
    const positions = {};
    for (const joint of state.config.joints) positions[joint.name] = toValue(joint, toStep(joint, joint.zero));
    setPositions(positions);
    publish();
  });
  document.getElementById("randomize").addEventListener("click", () => {
    const positions = {};
    for (const joint of state.config.joints) {
      const value = joint.min + Math.random() * (joint.max - joint.min);
      positions[joint.name] = toValue(joint, toStep(joint, value));  // what the slider can show
    }
    setPositions(positions);
    publish();
  });
  for (const [id, kind] of [["show-visuals", "visuals"], ["show-collisions", "collisions"], ["show-frames", "frames"]]) {
    document.getElementById(id).addEventListener("change", (event) => {
      send({type: "show", what: kind, visible: event.target.checked});
    });
  }
  connect();
})();
