// The participant page of `tlab serve`: shows the screen the server's session flow publishes and
// sends the participant's replies. It never sees a right answer (scoring happens on the server).
// Stimuli are shown at the size [online] stimulus_size asks (cssPerPixel below): native (whole
// device pixels, an integer upscale), css or a width in cm; RT runs from the frame the picture was
// first painted to the input.
// Every word it shows comes from the server's participant text table (in the experiment's
// language, with the file's [text] overrides; a JSON block of the page): t('button.continue').
// Over 300 lines: the whole page is one script, served as one file without a bundler; each screen
// kind is one function below.
'use strict';
const token = location.pathname.split('/')[2];
const api = (path) => '/api/' + token + '/' + path;
const main = document.getElementById('screen');
let current = null;      // the screen shown
let timers = [];         // cleared when the screen changes
let keyHandler = null;
let resizeHandler = null;
let cleanups = [];       // run when the screen changes (a live trial's key listener)
let settings = { stimulus_size: { mode: 'native' } };  // GET config
let pxPerCm = null;      // device pixels per cm, once calibrated
// key -> text: the experiment's participant text table, which the server writes into the page.
const texts = JSON.parse(document.getElementById('texts').textContent);

// The text of `key` with each {name} replaced by values[name]; the key itself if the table has none.
function t(key, values) {
  const text = Object.prototype.hasOwnProperty.call(texts, key) ? texts[key] : key;
  return text.replace(/\{([a-z_]+)\}/g, (whole, name) => (values && name in values ? String(values[name]) : whole));
}

// This browser's key, a cookie made once: the server binds a session to the browser that started
// it, so that knowing a participant id is not enough to take the session over from elsewhere.
(function browserKey() {
  if (/(?:^|;\s*)tlab-browser=[0-9a-f]{32}(?:;|$)/.test(document.cookie)) return;
  const bytes = crypto.getRandomValues(new Uint8Array(16));
  document.cookie = 'tlab-browser=' + Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('') + '; path=/; max-age=31536000; SameSite=Strict';
})();

// Leaving the page (back button, closing the tab) during a session asks first.
const inSession = () => current !== null && !['end', 'error'].includes(current.kind);
addEventListener('beforeunload', (e) => { if (inSession()) { e.preventDefault(); e.returnValue = ''; } });

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'class') e.className = v; else if (k.startsWith('on')) e.addEventListener(k.slice(2), v); else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function problem(text, retry) {
  document.getElementById('problem-text').textContent = text;
  const box = document.getElementById('problem');
  box.hidden = false;
  document.getElementById('problem-retry').onclick = () => { box.hidden = true; retry(); };
}

async function request(method, path, body) {
  let r;
  try {
    r = await fetch(api(path), { method, headers: body ? { 'Content-Type': 'application/json' } : {}, body: body ? JSON.stringify(body) : undefined, cache: 'no-store' });
  } catch (e) {
    return { status: 0, body: { error: t('page.connection_lost') } };
  }
  let json = {};
  try { json = await r.json(); } catch (e) { json = { error: t('page.unreadable') }; }
  if (r.status === 403) {  // the session belongs to another browser: nothing here can go on
    problem(t('page.other_browser'), () => location.reload());
    return new Promise(() => {});
  }
  return { status: r.status, body: json };
}

// Sends a reply to the screen on show; shows the next screen (the server's acknowledgement).
async function reply(body) {
  body.seq = current.seq;
  const r = await request('POST', 'reply', body);
  if (body.type === 'onset' || body.type === 'view') return r;
  if (r.status === 200) show(r.body);
  else if (r.status === 409) show(r.body.screen);
  else if (r.status === 400) showInlineError(r.body.error || '', body.type === 'answer', r.body.refusal);
  else {  // resolves with the reply to the retry: the caller learns how the answer finally fared
    return new Promise((resolve) => problem(t('page.not_saved', { error: r.body.error || t('page.server_error') }),
      () => resolve(reply(body))));
  }
  return r;
}

// A refused answer, said on the page; a form field's ("field 'age': ..." in the participants'
// language) below that field, in words without the field's id. A refused trial answer is said in
// the page's words, followed by the reason when the server names it by a text key (`refusal`:
// {key, args}, e.g. "Please type a whole number from 1 to 20."); the server's English reason stays
// in the element's title.
function showInlineError(text, answer, refusal) {
  main.querySelectorAll('.error').forEach((e) => e.remove());
  const m = /^field '([^']+)': (.*)$/.exec(text);
  const field = m && main.querySelector('.field[data-field="' + CSS.escape(m[1]) + '"]');
  if (field) {
    field.append(el('p', { class: 'error' }, t('form.check', { error: m[2] })));
    field.scrollIntoView({ block: 'nearest' });
  } else {
    const reason = refusal && refusal.key ? ' ' + t(refusal.key, refusal.args) : '';
    main.append(el('p', { class: 'error', title: text }, answer || !text ? t('trial.refused') + reason : text));
  }
}

async function poll() {
  const r = await request('GET', 'screen');
  if (r.status === 200) show(r.body);
  else problem(t('page.unreachable'), poll);
}

function clear() {
  timers.forEach((t) => clearInterval(t));
  timers = [];
  if (keyHandler) document.removeEventListener('keydown', keyHandler);
  keyHandler = null;
  if (resizeHandler) removeEventListener('resize', resizeHandler);
  resizeHandler = null;
  cleanups.forEach((f) => f());
  cleanups = [];
  document.getElementById('toosmall').hidden = true;
  main.replaceChildren();
}

function onKey(f) { keyHandler = f; document.addEventListener('keydown', f); }

function show(screen) {
  if (current && screen.seq === current.seq && screen.kind === current.kind && screen.kind !== 'wait') return;
  clear();
  current = screen;
  // What is shown, for the page's style sheet and for browser tests (tests/study/browser).
  main.dataset.kind = screen.kind;
  main.dataset.seq = screen.seq;
  if (screen.kind === 'trial') main.dataset.answerKind = screen.answer_kind; else delete main.dataset.answerKind;
  delete main.dataset.onset;
  const views = { message, consent, form, trial, feedback, break: pause, end, error: failed, wait, calibration };
  (views[screen.kind] || wait)(screen);
}

function wait() {
  main.append(el('p', { class: 'muted' }, t('page.wait')));
  timers.push(setTimeout(poll, 250));
}

function paragraphs(text) { return el('p', { class: 'text' }, text); }

function message(s) {
  const go = el('button', { type: 'button', id: 'continue', onclick: () => reply({ type: 'continue' }) }, t('button.continue'));
  main.append(el('h1', {}, s.title), paragraphs(s.text), go);
  onKey((e) => { if (e.key === ' ' || e.key === 'Enter') { e.preventDefault(); go.click(); } });
}

function consent(s) {
  main.append(el('h1', {}, s.title), paragraphs(s.text),
    el('button', { type: 'button', id: 'accept', onclick: () => reply({ type: 'consent', accepted: true }) }, s.accept),
    el('button', { type: 'button', id: 'decline', onclick: () => reply({ type: 'consent', accepted: false }) }, s.decline));
}

function fieldInput(f, i) {
  const name = 'f' + i;
  if (f.kind === 'likert' || f.kind === 'choice') {
    const options = f.kind === 'likert' ? Array.from({ length: f.points }, (_, k) => String(k + 1)) : f.options;
    const box = el('div', { role: 'radiogroup' });
    if (f.kind === 'likert') box.append(el('span', { class: 'muted' }, f.low + ' '));
    options.forEach((o) => box.append(el('label', {}, el('input', { type: 'radio', name, value: o }), ' ' + o)));
    if (f.kind === 'likert') box.append(el('span', { class: 'muted' }, ' ' + f.high));
    return [box, () => (main.querySelector('input[name=' + name + ']:checked') || { value: '' }).value];
  }
  const input = el('input', { type: f.kind === 'number' ? 'number' : 'text', name, step: f.integer ? '1' : 'any' });
  return [input, () => input.value.trim()];
}

function form(s) {
  const getters = [];
  main.append(el('h1', {}, s.title));
  s.fields.forEach((f, i) => {
    const [input, get] = fieldInput(f, i);
    getters.push(get);
    main.append(el('div', { class: 'field', 'data-field': f.id }, el('p', {}, f.required ? f.text : t('form.optional', { text: f.text })), input));
  });
  const go = el('button', { type: 'button', id: 'submit', onclick: () => {
    go.disabled = true;  // one submission in flight; a refused one gives the form back
    reply({ type: 'form', values: getters.map((g) => g()) }).then((r) => { if (current === s) go.disabled = false; });
  } }, t('button.continue'));
  main.append(go);
}

// How many CSS px one image pixel takes ([online] stimulus_size): native: k = ceil(devicePixelRatio)
// whole device pixels, so a picture is never smaller than its size in CSS px; css: 1; cm: the
// calibrated width (css without a calibration).
function cssPerPixel(image) {
  const size = settings.stimulus_size;
  if (size.mode === 'css') return 1;
  if (size.mode === 'cm' && pxPerCm) return size.cm * pxPerCm / devicePixelRatio / image.width;
  if (size.mode === 'cm') return 1;
  return Math.max(1, Math.ceil(devicePixelRatio - 1e-6)) / devicePixelRatio;
}

// The shown size of a picture, sent with its onset and stored with it: device and CSS pixels, cm.
function shownSize(image) {
  const scale = cssPerPixel(image), css = [image.width * scale, image.height * scale];
  const shown = { mode: settings.stimulus_size.mode, css_width: css[0], css_height: css[1],
    device_width: css[0] * devicePixelRatio, device_height: css[1] * devicePixelRatio, device_pixel_ratio: devicePixelRatio };
  if (pxPerCm) Object.assign(shown, { cm_width: css[0] * devicePixelRatio / pxPerCm, cm_height: css[1] * devicePixelRatio / pxPerCm });
  return shown;
}

// The session's stimulus size, stored with its display (a size in cm is known only after the
// calibration: each onset stores it).
function sessionSize(size) {
  const out = { stimulus_size: size.mode === 'cm' ? size.cm + 'cm' : size.mode };
  if (size.mode === 'cm') return out;
  const shown = shownSize({ width: size.width, height: size.height });
  return Object.assign(out, { stimulus_css_width: shown.css_width, stimulus_css_height: shown.css_height,
    stimulus_device_width: shown.device_width, stimulus_device_height: shown.device_height });
}

// The picture at the size stimulus_size asks; a warning when the window is too small for
// it (and for what stands beside it: besideWidth device pixels, the floor plan).
function picture(image, src, besideWidth = 0) {
  const img = el('img', { src, alt: t('trial.stimulus'), draggable: 'false' });
  const scale = cssPerPixel(image);
  img.style.width = image.width * scale + 'px';
  img.style.height = image.height * scale + 'px';
  if (Number.isInteger(scale * devicePixelRatio)) img.classList.add('native');  // whole device pixels: no smoothing
  const fits = () => {
    const width = (image.width + besideWidth) * scale + (besideWidth ? 64 : 40), height = image.height * scale + 160;
    const small = innerWidth < width || innerHeight < height;
    document.getElementById('toosmall-text').textContent = t('page.too_small', { size: Math.ceil(width) + ' × ' + Math.ceil(height) });
    document.getElementById('toosmall').hidden = !small;
  };
  fits();
  resizeHandler = fits;
  addEventListener('resize', fits);
  return img;
}

// Resolves with the time of the first frame painted with the decoded image (two animation frames).
function painted(img) {
  return img.decode().catch(() => {}).then(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
}

// The answer controls of the question's widget (the server sends the widget as data: the page draws
// the few widget primitives, never a task of its own).
function answerControls(s, stage, submit) {
  const box = el('div', { class: 'answer' });
  const w = s.widget;
  if (w.kind === 'number') {
    const input = el('input', { type: 'number', id: 'answer', min: String(w.min), step: '1' });
    const send = (e) => { if (/^\d+$/.test(input.value.trim())) submit(parseInt(input.value, 10), e); else showInlineError(t('trial.whole_number')); };
    input.addEventListener('keydown', (e) => { if (e.key === 'Enter') send(e); });
    box.append(input, el('button', { type: 'button', id: 'submit', onclick: send }, t('button.submit')));
    setTimeout(() => input.focus(), 0);
  } else if (w.kind === 'pick-label' || w.kind === 'pick-labels') {
    const chosen = new Set();
    s.labels.forEach((l) => {
      const hit = el('button', { type: 'button', class: 'hit', 'data-label': l.label, title: l.label });
      // A round hit box centred on the mark, at most 22 CSS px wide and never reaching past the
      // middle to the next mark: every mark is clickable where it is drawn, the nearest one wins.
      const k = cssPerPixel(s.image), x = l.x * k, y = l.y * k;
      const gap = Math.min(...s.labels.filter((o) => o !== l).map((o) => Math.hypot(o.x * k - x, o.y * k - y)));
      const size = Math.max(8, Math.min(22, gap - 1));
      Object.assign(hit.style, { left: x - size / 2 + 'px', top: y - size / 2 + 'px', width: size + 'px', height: size + 'px' });
      const button = el('button', { type: 'button', class: 'label', 'data-label': l.label }, l.label);
      const pick = (e) => {
        if (w.kind === 'pick-label') return submit(l.label, e);
        if (chosen.has(l.label)) chosen.delete(l.label); else chosen.add(l.label);
        hit.classList.toggle('selected', chosen.has(l.label));
        button.classList.toggle('selected', chosen.has(l.label));
      };
      hit.addEventListener('click', pick);
      button.addEventListener('click', pick);
      stage.append(hit);
      box.append(button);
    });
    if (w.kind === 'pick-labels') box.append(el('button', { type: 'button', id: 'submit', onclick: (e) => submit(Array.from(chosen), e) }, t('button.done')));
  } else if (w.kind === 'buttons') {
    w.buttons.forEach((l) => box.append(el('button', { type: 'button', class: 'letter', 'data-letter': l, onclick: (e) => submit(l, e) }, l)));
    onKey((e) => { const k = e.key.toUpperCase(); if (w.buttons.includes(k)) submit(k, e); });
  } else if (w.kind === 'gauge') {
    const g = gauge(s, stage);
    box.append(el('button', { type: 'button', id: 'submit', onclick: (e) => submit(g.setting(), e) }, t('button.done')));
    onKey((e) => { if (e.key === 'Enter') submit(g.setting(), e); else g.key(e); });
  }
  return box;
}

// The gauge figure over the picture (tasks/gauge_frame.hpp): a disk of radius R seen at slant σ and
// tilt τ is an ellipse of axes R and R cos σ, the short one along τ, with its stick to R sin σ (cos τ,
// −sin τ). Pressing or dragging on the picture points the stick at the pointer; the arrow keys turn
// it (up/down: slant ± 2°, left/right: tilt ± 5°). Every change is drawn at once; the orientation
// sent is the one shown.
function gauge(s, stage) {
  const w = s.widget.gauge;
  let slant = w.start[0], tilt = w.start[1], held = false;
  const canvas = el('canvas', { id: 'gauge', class: 'gauge' });
  stage.append(canvas);
  stage.classList.add('gauge-stage');
  const img = stage.querySelector('img');
  const scale = () => img.clientWidth / s.image.width;  // CSS px per stimulus pixel
  const draw = () => {
    const k = scale(), dpr = devicePixelRatio;
    canvas.width = Math.round(img.clientWidth * dpr);
    canvas.height = Math.round(img.clientHeight * dpr);
    canvas.style.width = img.clientWidth + 'px';
    canvas.style.height = img.clientHeight + 'px';
    const c = canvas.getContext('2d');
    c.setTransform(dpr, 0, 0, dpr, 0, 0);
    c.clearRect(0, 0, canvas.width, canvas.height);
    const x = w.x * k, y = w.y * k, r = w.radius * k, sr = slant * Math.PI / 180, tr = tilt * Math.PI / 180;
    [['#fff', 3.6], ['#c81e1e', 1.8]].forEach(([color, width]) => {
      c.strokeStyle = color;
      c.lineWidth = width;
      c.beginPath();
      c.ellipse(x, y, r * Math.cos(sr) + 0.01, r, -tr, 0, 2 * Math.PI);
      c.moveTo(x, y);
      c.lineTo(x + r * Math.sin(sr) * Math.cos(tr), y - r * Math.sin(sr) * Math.sin(tr));
      c.stroke();
    });
    stage.dataset.slant = slant.toFixed(3);
    stage.dataset.tilt = tilt.toFixed(3);
  };
  const toward = (ev) => {
    const box = img.getBoundingClientRect(), k = scale();
    const dx = (ev.clientX - box.left - w.x * k) / (w.radius * k), dy = -(ev.clientY - box.top - w.y * k) / (w.radius * k);
    slant = Math.asin(Math.min(Math.hypot(dx, dy), Math.sin(85 * Math.PI / 180))) * 180 / Math.PI;
    tilt = (Math.atan2(dy, dx) * 180 / Math.PI + 360) % 360;
    draw();
  };
  stage.addEventListener('pointerdown', (ev) => { held = true; stage.setPointerCapture(ev.pointerId); toward(ev); ev.preventDefault(); });
  stage.addEventListener('pointermove', (ev) => { if (held) toward(ev); });
  stage.addEventListener('pointerup', () => { held = false; });
  if (img.complete) draw(); else img.addEventListener('load', draw);
  addEventListener('resize', draw);
  return {
    setting: () => ({ slant, tilt }),
    key: (e) => {
      const turns = { ArrowUp: [2, 0], ArrowDown: [-2, 0], ArrowLeft: [0, 5], ArrowRight: [0, -5] }[e.key];
      if (!turns) return;
      slant = Math.min(85, Math.max(0, slant + turns[0]));
      tilt = ((tilt + turns[1]) % 360 + 360) % 360;
      e.preventDefault();
      draw();
    },
  };
}

function floorPlan(s, submit) {
  const img = el('img', { src: api('image/' + s.floor_plan.sha256 + '.png'), alt: t('trial.floor_plan'), id: 'floor-plan', draggable: 'false' });
  img.style.width = s.floor_plan.width * cssPerPixel(s.floor_plan) + 'px';
  img.style.height = s.floor_plan.height * cssPerPixel(s.floor_plan) + 'px';
  img.addEventListener('click', (e) => {
    // offsetX/Y: from the picture's own top-left corner, inside its border (the box's size would
    // include the border and shift and stretch the click).
    submit({ x: e.offsetX * s.floor_plan.width / img.clientWidth, y: e.offsetY * s.floor_plan.height / img.clientHeight }, e);
  });
  return el('div', { class: 'plan' }, img);
}

// Orbit trials online: drag through the pre-rendered views (every change is logged).
function turntable(s, stage, img) {
  const t = s.turntable;
  let a = t.start[0], e = t.start[1], dragging = null;
  const src = (ai, ei) => api('image/' + t.views[ei * t.azimuths + ai].sha256 + '.png');
  t.views.forEach((v) => { new Image().src = api('image/' + v.sha256 + '.png'); });
  stage.classList.add('turntable');
  const perStep = Math.max(4, 360 / t.azimuths);
  stage.addEventListener('pointerdown', (ev) => { dragging = { x: ev.clientX, y: ev.clientY, a, e }; stage.setPointerCapture(ev.pointerId); });
  // After a drag the answer box has the keyboard again (the count is typed right after turning).
  stage.addEventListener('pointerup', () => { dragging = null; const answer = document.getElementById('answer'); if (answer) answer.focus(); });
  stage.addEventListener('pointermove', (ev) => {
    if (!dragging) return;
    const na = ((dragging.a + Math.round((ev.clientX - dragging.x) / perStep)) % t.azimuths + t.azimuths) % t.azimuths;
    const ne = Math.min(t.elevations - 1, Math.max(0, dragging.e + Math.round((dragging.y - ev.clientY) / (perStep * 2))));
    if (na === a && ne === e) return;
    a = na; e = ne;
    img.src = src(a, e);
    reply({ type: 'view', azimuth: a, elevation: e, t_ms: performance.now() });
  });
  return src(a, e);
}

// Live trials (orbit, walk: [online] live): the server renders every view from the participant's
// input, with the window's camera arithmetic. The page sends only input — dragged picture pixels,
// arrow-key presses (Up/Down: forward/back, Left/Right: turn), wheel steps (forward/back), the
// cursor for a lens that follows it — and shows the PNG that comes back. One request is in
// flight at a time; input piles up meanwhile and goes with the next. The stage carries the frame
// shown (data-frame-index, data-frame-sha256: the server's log of it) for browser tests, and
// data-swapping while a new frame replaces the picture and these have not caught up with it.
function live(s, stage, img) {
  const L = s.live;
  let input = { dx: 0, dy: 0, forward: 0, turn: 0 }, point = null, inFlight = false, started = false, dragging = null, shown = null;
  stage.classList.add('live');
  stage.dataset.frames = '0';
  const moved = () => input.dx || input.dy || input.forward || input.turn || point;
  const send = async () => {
    if (inFlight || current !== s || (started && !moved())) return;
    inFlight = true;
    started = true;
    const body = { seq: s.seq, input: {} };
    for (const k of ['dx', 'dy', 'forward', 'turn']) if (input[k]) body.input[k] = input[k];
    if (point) body.input.point = point;
    input = { dx: 0, dy: 0, forward: 0, turn: 0 };
    point = null;
    let r = null;
    try {
      r = await fetch(api('view'), { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body), cache: 'no-store' });
    } catch (e) { r = null; }
    if (r && r.status === 200 && current === s) {
      const url = URL.createObjectURL(await r.blob());
      stage.dataset.swapping = '1';
      img.src = url;
      await img.decode().catch(() => {});
      if (shown) URL.revokeObjectURL(shown);
      shown = url;
      stage.dataset.frameIndex = r.headers.get('X-Frame-Index');
      stage.dataset.frameSha256 = r.headers.get('X-Frame-Sha256');
      stage.dataset.frames = String(Number(stage.dataset.frames) + 1);
      delete stage.dataset.swapping;
    } else if (r && r.status === 409) {
      const b = await r.json().catch(() => ({}));
      if (b.screen && b.screen.seq > s.seq) show(b.screen);
    } else if (r && r.status === 403) {
      problem(t('page.other_browser'), () => location.reload());
    }
    inFlight = false;
    if (moved()) timers.push(setTimeout(send, r && r.status === 200 ? 0 : 500));
  };
  const scale = () => s.image.width / img.clientWidth;  // picture pixels per CSS px
  stage.addEventListener('pointerdown', (ev) => { dragging = { x: ev.clientX, y: ev.clientY }; stage.setPointerCapture(ev.pointerId); ev.preventDefault(); });
  stage.addEventListener('pointerup', () => { dragging = null; const answer = document.getElementById('answer'); if (answer) answer.focus(); });
  stage.addEventListener('pointermove', (ev) => {
    if (dragging) {
      input.dx += (ev.clientX - dragging.x) * scale();
      input.dy += (ev.clientY - dragging.y) * scale();
      dragging = { x: ev.clientX, y: ev.clientY };
    }
    if (L.lens) {
      const box = img.getBoundingClientRect();
      point = [Math.min(1, Math.max(0, (ev.clientX - box.left) / box.width)), Math.min(1, Math.max(0, (ev.clientY - box.top) / box.height))];
    }
    send();
  });
  stage.addEventListener('wheel', (ev) => { ev.preventDefault(); input.forward += ev.deltaY < 0 ? 1 : -1; send(); }, { passive: false });
  const keys = (e) => {
    const step = { ArrowUp: [1, 0], ArrowDown: [-1, 0], ArrowLeft: [0, -1], ArrowRight: [0, 1] }[e.key];
    if (!step) return;
    e.preventDefault();
    input.forward += step[0];
    input.turn += step[1];
    send();
  };
  document.addEventListener('keydown', keys);
  cleanups.push(() => { document.removeEventListener('keydown', keys); if (shown) URL.revokeObjectURL(shown); });
  send();  // the start view
}

// How to answer with the mouse or keys: the text of answer.<answer kind> (answer.typed for a kind
// the table does not know).
function hint(s) {
  return t(('answer.' + s.answer_kind) in texts ? 'answer.' + s.answer_kind : 'answer.typed');
}

// After a refused answer the trial takes answers again: the number box is focused with its text
// selected, so the corrected answer is simply typed over it.
function answerAgain() {
  const box = document.getElementById('answer');
  if (box) { box.focus(); box.select(); }
}

// The time limit ran out: the page says so, takes no more input, and then tells the server.
function timeUp() {
  main.querySelectorAll('input, button').forEach((e) => { e.disabled = true; });
  main.querySelectorAll('.error').forEach((e) => e.remove());
  const hint = document.getElementById('hint');
  const note = el('p', { class: 'time-up', id: 'time-up', role: 'alert' }, t('trial.time_up'));
  if (hint) hint.replaceWith(note); else main.append(note);
  timers.push(setTimeout(() => reply({ type: 'timeout' }), 1500));
}

function trial(s) {
  let onset = null, done = false;
  if (typeof s.px_per_cm === 'number') pxPerCm = s.px_per_cm;  // the participant's calibration, kept by the server
  // One answer in flight at a time; a refused one (400) gives the trial back to the participant.
  const submit = (answer, ev) => {
    if (done || onset === null) return;
    done = true;
    const at = ev && ev.timeStamp ? ev.timeStamp : performance.now();
    reply({ type: 'answer', answer, rt_ms: Math.max(0, at - onset), painted_ms: onset, input_ms: at }).then((r) => {
      if (current !== s || r.status !== 400) return;
      done = false;
      answerAgain();
    });
  };
  const stage = el('div', { class: 'stage', id: 'stage' });
  const img = picture(s.image, api('image/' + s.image.sha256 + '.png'), s.floor_plan ? s.floor_plan.width : 0);
  if (s.turntable) img.src = turntable(s, stage, img);
  stage.append(img);
  if (s.live) live(s, stage, img);
  const clock = el('span', { class: 'countdown', id: 'countdown', title: t('trial.time_left') }, '');
  const progress = t(s.phase === 'training' ? 'trial.progress_practice' : 'trial.progress_test', { index: s.index, total: s.total });
  main.append(el('div', { class: 'top' }, el('span', { class: 'muted progress' }, progress), clock),
    el('h1', { class: 'question' }, s.question));
  const row = el('div', { class: 'row' }, stage);
  if (s.floor_plan) row.append(floorPlan(s, submit));
  // A live trial says how to move (drag and keys, the lens that follows the pointer) above the hint.
  const moving = s.live ? [el('p', { class: 'muted', id: 'navigation' }, t('live.' + s.live.navigation) + (s.live.lens ? ' ' + t('live.lens') : ''))] : [];
  main.append(row, ...moving, el('p', { class: 'muted', id: 'hint' }, hint(s)), answerControls(s, stage, submit));
  painted(img).then((t) => {
    if (current !== s) return;
    onset = t;
    reply({ type: 'onset', painted_ms: t, shown: shownSize(s.image) }).then(() => { if (current === s) main.dataset.onset = 'reported'; });
    // The time limit runs from the first showing (as on the server): after a reload of the page
    // the countdown goes on where it was, it does not start again.
    const key = 'tlab-shown-' + token + '-' + s.seq;
    const first = Number(sessionStorage.getItem(key)) || Date.now();
    sessionStorage.setItem(key, String(first));
    const before = Math.max(0, Date.now() - first) / 1000;
    const tick = () => {
      const left = Math.max(0, s.limit_s - before - (performance.now() - onset) / 1000);
      clock.textContent = Math.floor(left / 60) + ':' + String(Math.floor(left % 60)).padStart(2, '0');
      if (left <= 0 && !done) { done = true; timeUp(); }
    };
    tick();
    timers.push(setInterval(tick, 250));
  });
}

function feedback(s) {
  const go = el('button', { type: 'button', id: 'continue', onclick: () => reply({ type: 'continue' }) }, t('button.continue'));
  const given = s.given === null || s.given === undefined ? t('feedback.none') : s.given;
  main.append(el('h1', {}, t(s.correct ? 'feedback.correct' : 'feedback.wrong')),
    el('p', { class: 'text', id: 'given' }, t('feedback.given', { answer: given })),
    el('p', { class: 'text', id: 'right' }, t('feedback.right', { answer: s.right_answer })),
    picture(s.image, api('image/' + s.image.sha256 + '.png')), el('p', {}, go));
  onKey((e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); go.click(); } });
}

function pause(s) {
  const go = el('button', { type: 'button', id: 'continue', disabled: 'disabled', onclick: () => reply({ type: 'continue' }) }, t('button.continue'));
  const left = el('span', { class: 'muted' }, '');
  const until = performance.now() + s.min_seconds * 1000;
  const tick = () => {
    const rest = Math.ceil((until - performance.now()) / 1000);
    left.textContent = rest > 0 ? ' ' + t('break.wait', { n: rest }) : '';
    if (rest <= 0) go.removeAttribute('disabled');
  };
  tick();
  timers.push(setInterval(tick, 250));
  main.append(el('h1', {}, t('break.title')), paragraphs(s.text), go, left);
  onKey((e) => { if (e.key === 'Enter' && !go.disabled) { e.preventDefault(); go.click(); } });
}

function end(s) {
  main.append(el('h1', {}, s.title), paragraphs(s.text));
  if (s.completion_code) main.append(el('p', {}, t('end.completion_code') + ' ', el('strong', { id: 'completion-code' }, s.completion_code)));
  if (s.completion_url) main.append(el('p', {}, el('a', { href: s.completion_url, id: 'completion-link' }, t('end.return_link'))));
}

function failed(s) {
  main.append(el('h1', {}, t('end.problem_title')), paragraphs(s.text));
  if (s.retry) main.append(el('button', { type: 'button', id: 'retry', onclick: () => start() }, t('button.try_again')));
}

// The refresh rate, estimated from the median interval of 30 animation frames.
function refreshRate() {
  return new Promise((resolve) => {
    const times = [];
    const step = (t) => { times.push(t); if (times.length < 31) requestAnimationFrame(step); else {
      const d = times.slice(1).map((x, i) => x - times[i]).sort((x, y) => x - y);
      resolve(Math.round(1000 / d[15]));
    } };
    requestAnimationFrame(step);
  });
}

// desktop, tablet or phone ([online] devices): touch-only when the primary pointer is coarse and
// cannot hover; a phone when its screen is also under 600 CSS px on its short side.
function deviceKind() {
  if (!matchMedia('(pointer: coarse)').matches || matchMedia('(hover: hover)').matches) return 'desktop';
  return Math.min(screen.width, screen.height) < 600 ? 'phone' : 'tablet';
}

// The credit-card method ("virtual chinrest"), after consent: a card is 8.56 cm wide. The rectangle
// is sized by a slider as wide as the page, by the − and + buttons and by the arrow keys (0.25 CSS
// px a step); "Done" needs at least one adjustment. The server keeps the value for the participant.
function calibration(s) {
  let adjustments = 0;
  const card = el('div', { class: 'card', id: 'card' });
  const slider = el('input', { type: 'range', min: '150', max: '900', step: '0.25', value: '320', id: 'card-size', 'aria-label': t('calibration.slider') });
  const size = () => { card.style.width = slider.value + 'px'; card.style.height = slider.value * 53.98 / 85.6 + 'px'; };
  const adjust = (step) => { slider.value = String(Number(slider.value) + step); adjustments += 1; size(); };
  slider.addEventListener('input', () => { adjustments += 1; size(); });
  size();
  const done = el('button', { type: 'button', id: 'calibrated', onclick: () => {
    if (adjustments === 0) return showInlineError(t('calibration.not_moved'));
    const width = Number(slider.value);
    reply({ type: 'calibration', skipped: false, px_per_cm: width * devicePixelRatio / 8.56, card_css_px: width, device_pixel_ratio: devicePixelRatio, adjustments });
  } }, t('calibration.done'));
  main.append(el('h1', {}, t('calibration.title')), paragraphs(t('calibration.text')), el('p', { class: 'muted' }, t('calibration.how')),
    el('div', { class: 'calibration' },
      el('button', { type: 'button', id: 'card-smaller', title: t('calibration.smaller'), 'aria-label': t('calibration.smaller'), onclick: () => adjust(-0.25) }, '−'),
      slider,
      el('button', { type: 'button', id: 'card-larger', title: t('calibration.larger'), 'aria-label': t('calibration.larger'), onclick: () => adjust(0.25) }, '+')),
    card, el('p', {}, done));
  if (s.no_card) main.append(el('p', {}, el('button', { type: 'button', id: 'no-card', onclick: () => reply({ type: 'calibration', skipped: true, adjustments }) }, t('calibration.no_card'))));
  onKey((e) => {  // the arrow keys and + / - move the edge wherever the focus is (the slider's own keys too)
    const step = { ArrowLeft: -0.25, ArrowDown: -0.25, '-': -0.25, ArrowRight: 0.25, ArrowUp: 0.25, '+': 0.25 }[e.key];
    if (step === undefined) return;
    e.preventDefault();
    adjust(step);
  });
}

async function start() {
  current = null;
  const config = await request('GET', 'config');
  if (config.status !== 200) return problem(t('page.invalid_link'), start);
  document.title = config.body.title;
  settings = config.body;
  const display = {
    device: deviceKind(), max_touch_points: navigator.maxTouchPoints || 0,
    ...sessionSize(settings.stimulus_size),
    screen_width: screen.width, screen_height: screen.height, window_width: innerWidth, window_height: innerHeight,
    device_pixel_ratio: devicePixelRatio, user_agent: navigator.userAgent.slice(0, 300), refresh_hz: await refreshRate(),
  };
  const r = await request('POST', 'display', display);
  if (r.status === 200) show(r.body); else problem(r.body.error || t('page.could_not_start'), start);
}

setInterval(() => request('GET', 'screen').then((r) => { if (r.status === 200 && current && r.body.seq > current.seq) show(r.body); }), 30000);
start();
