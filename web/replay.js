// The html replay of a tumble render (docs/scene-reference.md, [output] formats): the render's
// glTF (bodies, planes, one LINEAR animation of every body's pose at every frame time) played
// with three.js, under the scene's camera, with the render's 3D overlays (arrows of vectors and
// axes, trails) drawn from the same frames. Everything comes from the page itself: the data and
// the GLB in two <script> elements, three.js in the TumbleThree global (three-entry.js).
//
// For tests and scripts: the fragment #t=2&paused&speed=0.5 chooses the start; the page sets
// body[data-ready] once the scene is loaded (body[data-error] with the message if it cannot
// load), and window.tumbleReplay has ready (a promise), seek(t), play(), pause(), time(),
// playing(), snapshot() (the 3D view drawn at the video's size, as a PNG data: URL), scene
// (three.js's, the glTF's nodes named as the bodies) and camera.
(() => {
  'use strict';
  const { THREE, GLTFLoader, OrbitControls } = TumbleThree;
  const data = JSON.parse(document.getElementById('tumble-replay-data').textContent);
  const stage = document.getElementById('stage');
  const labelLayer = document.getElementById('labels');
  const slider = document.getElementById('time-slider');
  const timeText = document.getElementById('time');
  const playButton = document.getElementById('play');
  const speedChoice = document.getElementById('speed');
  const overlayChoice = document.getElementById('overlays');
  const videoCameraChoice = document.getElementById('video-camera');

  // The frames the data holds: first_frame .. first_frame + frames - 1, frame k at k / fps (s).
  const startTime = data.first_frame / data.fps;
  const endTime = (data.first_frame + data.frames - 1) / data.fps;
  const aspect = data.width / data.height;

  const options = fragmentOptions(location.hash);
  let time = Math.min(Math.max(options.t ?? startTime, startTime), endTime);  // s
  let playing = !options.paused;
  let speed = options.speed ?? 1;
  let followVideoCamera = data.camera_path !== null;
  let lastTick = null;  // ms, of the previous animation frame while playing

  // #t=2&paused&speed=0.5: each a number or a bare flag.
  function fragmentOptions(hash) {
    const out = {};
    for (const part of hash.replace(/^#/, '').split('&')) {
      if (!part) continue;
      const [key, value] = part.split('=');
      if (key === 'paused') out.paused = true;
      else if ((key === 't' || key === 'speed') && Number.isFinite(Number(value))) {
        out[key] = Number(value);
      }
    }
    return out;
  }

  function srgb(c) {
    return new THREE.Color().setRGB(c[0], c[1], c[2], THREE.SRGBColorSpace);
  }

  function vector(values, index) {
    return new THREE.Vector3(values[3 * index], values[3 * index + 1], values[3 * index + 2]);
  }

  // A per-frame array of 3-vectors at time t (s): linear between the two frames around t.
  function sampled(values, t) {
    const u = Math.min(Math.max((t - startTime) * data.fps, 0), data.frames - 1);
    const i = Math.min(Math.floor(u), data.frames - 2);
    if (i < 0) return vector(values, 0);
    return vector(values, i).lerp(vector(values, i + 1), u - i);
  }

  // --- the picture: renderer, camera, lights, ground ---
  const renderer = new THREE.WebGLRenderer({ antialias: true, alpha: data.transparent });
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  stage.prepend(renderer.domElement);
  const scene = new THREE.Scene();
  if (!data.transparent) scene.background = srgb(data.background);

  const camera = new THREE.PerspectiveCamera(data.camera.fov_degrees, aspect, 0.01, 1000);
  const controls = new OrbitControls(camera, renderer.domElement);
  function placeCamera(position, lookAt, fovDegrees, up) {
    camera.up.copy(up).normalize();
    camera.position.copy(position);
    camera.fov = fovDegrees;
    // Near and far grow with the distance to the point looked at, as tumble's renderer's do.
    const distance = position.distanceTo(lookAt);
    camera.near = Math.max(0.01, 0.01 * distance);
    camera.far = 200 * distance + 200;
    camera.updateProjectionMatrix();
    controls.target.copy(lookAt);
    camera.lookAt(lookAt);
    controls.update();
  }
  function sceneCamera() {
    placeCamera(new THREE.Vector3().fromArray(data.camera.position),
                new THREE.Vector3().fromArray(data.camera.look_at), data.camera.fov_degrees,
                new THREE.Vector3().fromArray(data.camera.up));
  }
  function videoCamera(t) {
    const path = data.camera_path;
    const u = Math.min(Math.max(Math.round((t - startTime) * data.fps), 0), data.frames - 1);
    placeCamera(sampled(path.position, t), sampled(path.look_at, t), path.fov_degrees[u],
                sampled(path.up, t));
  }
  sceneCamera();
  controls.addEventListener('start', () => {  // the user takes the camera
    followVideoCamera = false;
    videoCameraChoice.checked = false;
  });

  // tumble's light: a key light along `direction`, and an ambient term that is brighter facing
  // up (the sky) than facing down (0.55: the bounce), docs/scene-reference.md "Lighting". three's
  // Lambert term divides by π, so the intensities carry a π to give albedo × n·l.
  const lightColor = srgb(data.light.color);
  const key = new THREE.DirectionalLight(lightColor, Math.PI);
  key.position.fromArray(data.light.direction).normalize().multiplyScalar(-50);
  scene.add(key, key.target);
  scene.add(new THREE.HemisphereLight(lightColor.clone().multiplyScalar(data.light.ambient),
                                      lightColor.clone().multiplyScalar(0.55 * data.light.ambient),
                                      Math.PI));

  const ground = data.ground && !data.transparent ? groundOf(data.ground) : null;
  if (ground) scene.add(ground);

  // A canvas of `size` px as a texture, drawn by `paint(context, size)`.
  function paintedTexture(size, paint) {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = size;
    paint(canvas.getContext('2d'), size);
    const texture = new THREE.CanvasTexture(canvas);
    texture.anisotropy = renderer.capabilities.getMaxAnisotropy();
    return texture;
  }

  // The ground as tumble draws it (shaders/ground.frag): matte, its grid lines 0.65 of its colour
  // at every grid_spacing, fading into the background from 0.35 of its half extent about the
  // point the camera looks at to the whole of it (placeGround moves it there). It stands in for
  // the glTF's "ground" node, the unfaded square alone.
  function groundOf(ground) {
    const half = ground.half_extent;  // m
    const material = new THREE.MeshStandardMaterial({
      color: srgb(ground.color), roughness: 1, metalness: 0, transparent: true, depthWrite: true });
    if (ground.grid_spacing > 0) {
      material.map = paintedTexture(256, (context, size) => {
        context.fillStyle = '#fff';
        context.fillRect(0, 0, size, size);
        context.fillStyle = `rgb(${Math.round(255 * 0.65 ** (1 / 2.2))}, ` +
                            `${Math.round(255 * 0.65 ** (1 / 2.2))}, ${Math.round(255 * 0.65 ** (1 / 2.2))})`;
        context.fillRect(0, 0, size, 2);
        context.fillRect(0, 0, 2, size);
      });
      material.map.colorSpace = THREE.SRGBColorSpace;
      material.map.wrapS = material.map.wrapT = THREE.RepeatWrapping;
      const cells = 2 * half / ground.grid_spacing;
      material.map.repeat.set(cells, cells);
    }
    material.alphaMap = paintedTexture(256, (context, size) => {
      const fade = context.createRadialGradient(size / 2, size / 2, 0.35 * size / 2,
                                                size / 2, size / 2, size / 2);
      fade.addColorStop(0, '#fff');
      fade.addColorStop(1, '#000');
      context.fillStyle = fade;
      context.fillRect(0, 0, size, size);
    });
    const plane = new THREE.Mesh(new THREE.PlaneGeometry(2 * half, 2 * half), material);
    plane.rotation.x = -Math.PI / 2;
    plane.position.y = ground.height;
    plane.receiveShadow = true;
    plane.renderOrder = -1;  // before the bodies, which it never covers
    return plane;
  }

  // The key light's shadows over the bodies' reach: an orthographic box about `centre` of
  // `radius` (m), as tumble's shadow map.
  function castShadows(centre, radius) {
    renderer.shadowMap.enabled = true;
    renderer.shadowMap.type = THREE.PCFSoftShadowMap;
    key.castShadow = true;
    key.shadow.mapSize.set(2048, 2048);
    const along = new THREE.Vector3().fromArray(data.light.direction).normalize();
    key.target.position.copy(centre);
    key.position.copy(centre).addScaledVector(along, -2 * radius);
    Object.assign(key.shadow.camera, { left: -radius, right: radius, top: radius,
                                       bottom: -radius, near: 0.1, far: 4 * radius + 0.1 });
    key.shadow.camera.updateProjectionMatrix();
    key.shadow.bias = -0.0005;
    key.shadow.normalBias = 0.01 * radius;
  }

  // --- overlays: arrows (vectors, axes) and trails, one entry per overlay item of the frames ---
  const overlays = new THREE.Group();
  overlays.renderOrder = 10;
  scene.add(overlays);
  const arrows = data.arrows.map((arrow) => {
    const helper = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1,
                                         srgb(arrow.color));
    for (const part of [helper.line, helper.cone]) {
      part.material.depthTest = false;  // over the scene, as tumble draws overlays
      part.material.transparent = true;
      part.material.opacity = arrow.color[3];
      part.renderOrder = 10;
    }
    overlays.add(helper);
    let label = null;
    if (arrow.label) {
      label = document.createElement('span');
      label.textContent = arrow.label;
      label.style.color = srgb(arrow.color).getStyle();
      labelLayer.append(label);
    }
    return { arrow, helper, label, tip: new THREE.Vector3() };
  });
  const trails = data.trails.map((trail) => {
    const geometry = new THREE.BufferGeometry();
    const line = new THREE.Line(geometry, new THREE.LineBasicMaterial({
      color: srgb(trail.color), vertexColors: true, transparent: true, depthTest: false }));
    line.renderOrder = 10;
    line.frustumCulled = false;
    overlays.add(line);
    return { trail, geometry };
  });

  function updateArrows(t) {
    for (const entry of arrows) {
      const { arrow, helper } = entry;
      const from = sampled(arrow.from, t);
      entry.tip = sampled(arrow.to, t);
      const along = entry.tip.clone().sub(from);
      const length = along.length();
      helper.visible = length > 1e-9;
      if (!helper.visible) continue;
      helper.position.copy(from);
      helper.setDirection(along.divideScalar(length));
      const head = Math.min(0.25 * length, 0.15);  // m
      helper.setLength(length, head, 0.5 * head);
    }
  }

  // The trail of frames within `length` seconds before t, and the point at t, fading from 1 at
  // the body to 0 at `length` seconds old (as view/overlay_view.cpp draws it).
  function updateTrails(t) {
    for (const { trail, geometry } of trails) {
      const positions = [];
      const colors = [];
      const add = (point, age) => {
        positions.push(point.x, point.y, point.z);
        colors.push(1, 1, 1, trail.color[3] * Math.max(0, 1 - age / trail.length));
      };
      const newest = Math.floor((t - startTime) * data.fps + 1e-6);
      const oldest = Math.ceil((t - trail.length - startTime) * data.fps - 1e-6);
      for (let k = Math.max(0, oldest); k <= Math.min(newest, data.frames - 1); ++k) {
        add(vector(trail.points, k), t - (startTime + k / data.fps));
      }
      add(sampled(trail.points, t), 0);
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
      geometry.setAttribute('color', new THREE.Float32BufferAttribute(colors, 4));
    }
  }

  // Each arrow's label just right of its tip on the picture, while the arrow is drawn and the
  // tip is in front of the camera.
  function placeLabels() {
    const width = renderer.domElement.clientWidth;
    const height = renderer.domElement.clientHeight;
    const left = renderer.domElement.offsetLeft;
    const top = renderer.domElement.offsetTop;
    for (const { helper, label, tip } of arrows) {
      if (!label) continue;
      const ndc = tip.clone().project(camera);
      label.hidden = !overlays.visible || !helper.visible || ndc.z > 1;
      label.style.left = `${left + (ndc.x + 1) / 2 * width}px`;
      label.style.top = `${top + (1 - ndc.y) / 2 * height}px`;
    }
  }

  // --- playing ---
  let mixer = null;
  let action = null;

  function show(t) {
    if (action) {
      action.time = t;
      mixer.update(0);  // evaluates the clip at action.time
    }
    if (followVideoCamera) videoCamera(t);
    updateArrows(t);
    updateTrails(t);
    slider.value = t;
    timeText.value = `${t.toFixed(2)} s / ${endTime.toFixed(2)} s`;
  }

  // The ground's square under the point looked at, its grid lines kept at whole multiples of
  // the spacing in the world, as the video's.
  function placeGround(centre) {
    ground.position.x = centre.x;
    ground.position.z = centre.z;
    const map = ground.material.map;
    if (!map) return;
    const spacing = data.ground.grid_spacing;
    const half = data.ground.half_extent;
    // u runs along x from centre.x − half; v along −z from centre.z + half (the plane's rotation).
    map.offset.set(((centre.x - half) / spacing) % 1, ((-centre.z - half) / spacing) % 1);
  }

  function draw() {
    if (ground) placeGround(controls.target);
    renderer.render(scene, camera);
    placeLabels();
  }

  // Draws on the next animation frame: while playing every one, else only after a change.
  let drawPending = false;
  function redraw() {
    drawPending = true;
  }

  function tick(now) {
    if (playing) {
      if (lastTick !== null) {
        time += (now - lastTick) / 1000 * speed;
        if (time > endTime) {  // loops
          time = startTime + (time - endTime) % Math.max(endTime - startTime, 1e-9);
        }
        show(time);
      }
      lastTick = now;
    }
    if (playing || drawPending) draw();
    drawPending = false;
    requestAnimationFrame(tick);
  }

  // The canvas as large as the stage holds at the video's aspect, so that the picture is the
  // video's whatever the window.
  function fit() {
    const width = Math.max(1, Math.min(stage.clientWidth, stage.clientHeight * aspect));
    renderer.setPixelRatio(window.devicePixelRatio);
    renderer.setSize(Math.floor(width), Math.floor(width / aspect));
    draw();
  }

  function setPlaying(on) {
    playing = on;
    lastTick = null;
    playButton.textContent = on ? 'Pause' : 'Play';
  }

  function seek(t) {
    time = Math.min(Math.max(Number(t), startTime), endTime);
    show(time);
    draw();
    return time;
  }

  // The 3D view at the video's size (px) as a PNG data: URL, drawn and read in one task.
  function snapshot() {
    const size = renderer.getSize(new THREE.Vector2());
    const ratio = renderer.getPixelRatio();
    renderer.setPixelRatio(1);
    renderer.setSize(data.width, data.height, false);
    renderer.render(scene, camera);
    const url = renderer.domElement.toDataURL('image/png');
    renderer.setPixelRatio(ratio);
    renderer.setSize(size.x, size.y, false);
    draw();
    return url;
  }

  // The box the moving bodies sweep over the frames (a still scene's: every mesh but the ground).
  function bodiesReach(gltf) {
    const reach = new THREE.Box3();
    const moving = new Set((gltf.animations[0]?.tracks ?? []).map(
      (track) => THREE.PropertyBinding.parseTrackName(track.name).nodeName));
    const bodies = [];
    gltf.scene.traverse((object) => {
      if (object.isMesh && object.name !== 'ground' &&
          (moving.size === 0 || moving.has(object.name) || moving.has(object.parent?.name))) {
        bodies.push(object);
      }
    });
    const samples = action ? 32 : 1;
    for (let i = 0; i < samples; ++i) {
      if (action) {
        action.time = startTime + (endTime - startTime) * i / (samples - 1);
        mixer.update(0);
      }
      for (const body of bodies) reach.expandByObject(body);
    }
    return reach.isEmpty() ? new THREE.Box3(new THREE.Vector3(-1, -1, -1),
                                            new THREE.Vector3(1, 1, 1)) : reach;
  }

  function fail(message) {
    const box = document.getElementById('message');
    box.textContent = `This replay cannot be shown: ${message}`;
    box.hidden = false;
    document.body.dataset.error = message;
  }

  function glbBytes() {
    const text = atob(document.getElementById('tumble-replay-glb').textContent.trim());
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return bytes.buffer;
  }

  const ready = new GLTFLoader().parseAsync(glbBytes(), '').then((gltf) => {
    scene.add(gltf.scene);
    const glbGround = gltf.scene.getObjectByName('ground');
    if (glbGround && data.ground && !data.transparent) glbGround.visible = false;
    gltf.scene.traverse((object) => {
      if (object.isMesh) object.castShadow = object.receiveShadow = true;
    });
    if (gltf.animations.length > 0) {
      mixer = new THREE.AnimationMixer(gltf.scene);
      action = mixer.clipAction(gltf.animations[0]);
      action.setLoop(THREE.LoopOnce);
      action.clampWhenFinished = true;
      action.play();
    }
    if (data.shadows) {
      const reach = bodiesReach(gltf);
      castShadows(reach.getCenter(new THREE.Vector3()),
                  Math.max(1, reach.getBoundingSphere(new THREE.Sphere()).radius));
    }
    show(time);
    fit();
    document.body.dataset.ready = 'true';
    requestAnimationFrame(tick);
  });
  ready.catch((error) => fail(String(error && error.message || error)));

  document.title = `${data.name}: tumble replay`;
  slider.min = startTime;
  slider.max = endTime;
  slider.step = 1 / data.fps;
  speedChoice.value = String(speed);
  if (speedChoice.value !== String(speed)) {  // a speed the list lacks, from the fragment
    speedChoice.append(new Option(`${speed}×`, String(speed), true, true));
  }
  setPlaying(playing);
  overlays.visible = overlayChoice.checked;
  document.getElementById('video-camera-choice').hidden = data.camera_path === null;

  playButton.addEventListener('click', () => setPlaying(!playing));
  slider.addEventListener('input', () => seek(slider.value));
  speedChoice.addEventListener('change', () => { speed = Number(speedChoice.value); });
  overlayChoice.addEventListener('change', () => {
    overlays.visible = overlayChoice.checked;
    show(time);
    redraw();
  });
  videoCameraChoice.addEventListener('change', () => {
    followVideoCamera = videoCameraChoice.checked;
    if (!followVideoCamera) sceneCamera();
    show(time);
    redraw();
  });
  document.getElementById('reset-camera').addEventListener('click', () => {
    followVideoCamera = false;
    videoCameraChoice.checked = false;
    sceneCamera();
    redraw();
  });
  document.addEventListener('keydown', (event) => {
    if (event.code === 'Space' && event.target.tagName !== 'BUTTON') {
      event.preventDefault();
      setPlaying(!playing);
    }
  });
  controls.addEventListener('change', redraw);
  window.addEventListener('resize', fit);

  window.tumbleReplay = {
    ready,
    seek,
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    time: () => time,
    playing: () => playing,
    snapshot,
    scene,
    camera,
  };
})();
