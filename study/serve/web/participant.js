// The participant page of `tlab serve`: shows the screen the server's session flow publishes and
// sends the participant's replies. It never sees a right answer (scoring happens on the server).
// Stimuli are shown at their rendered size in device pixels (CSS size = pixels / devicePixelRatio),
// never scaled by the browser; RT runs from the frame the picture was first painted to the input.
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
    return { status: 0, body: { error: 'The connection to the study server was lost.' } };
  }
  let json = {};
  try { json = await r.json(); } catch (e) { json = { error: 'The server sent an unreadable reply.' }; }
  if (r.status === 403) {  // the session belongs to another browser: nothing here can go on
    problem('This session is open in another browser or on another device. Please continue there. If you closed it, ' +
      'this page can take the session over once it has been idle for the time-out.', () => location.reload());
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
  else if (r.status === 400) showInlineError(r.body.error || 'This answer was not accepted.');
  else {  // resolves with the reply to the retry: the caller learns how the answer finally fared
    return new Promise((resolve) => problem('Your answer could not be saved (' + (r.body.error || 'server error') + '). Please check your connection and try again.',
      () => resolve(reply(body))));
  }
  return r;
}

// A refused answer, said on the page; a form field's ("field 'age': ...") below that field, in
// words without the field's id.
function showInlineError(text) {
  main.querySelectorAll('.error').forEach((e) => e.remove());
  const m = /^field '([^']+)': (.*)$/.exec(text);
  const field = m && main.querySelector('.field[data-field="' + CSS.escape(m[1]) + '"]');
  if (field) {
    field.append(el('p', { class: 'error' }, 'Please check this answer: ' + m[2] + '.'));
    field.scrollIntoView({ block: 'nearest' });
  } else {
    main.append(el('p', { class: 'error' }, text));
  }
}

async function poll() {
  const r = await request('GET', 'screen');
  if (r.status === 200) show(r.body);
  else problem('The study server cannot be reached. Please check your connection.', poll);
}

function clear() {
  timers.forEach((t) => clearInterval(t));
  timers = [];
  if (keyHandler) document.removeEventListener('keydown', keyHandler);
  keyHandler = null;
  if (resizeHandler) removeEventListener('resize', resizeHandler);
  resizeHandler = null;
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
  const views = { message, consent, form, trial, feedback, break: pause, end, error: failed, wait };
  (views[screen.kind] || wait)(screen);
}

function wait() {
  main.append(el('p', { class: 'muted' }, 'Please wait…'));
  timers.push(setTimeout(poll, 250));
}

function paragraphs(text) { return el('p', { class: 'text' }, text); }

function message(s) {
  const go = el('button', { type: 'button', id: 'continue', onclick: () => reply({ type: 'continue' }) }, 'Continue');
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
    main.append(el('div', { class: 'field', 'data-field': f.id }, el('p', {}, f.text + (f.required ? '' : ' (optional)')), input));
  });
  const go = el('button', { type: 'button', id: 'submit', onclick: () => {
    go.disabled = true;  // one submission in flight; a refused one gives the form back
    reply({ type: 'form', values: getters.map((g) => g()) }).then((r) => { if (current === s) go.disabled = false; });
  } }, 'Continue');
  main.append(go);
}

// The picture at its rendered size in device pixels; a warning when the window is too small for
// it (and for what stands beside it: besideWidth device pixels, the floor plan).
function picture(image, src, besideWidth = 0) {
  const img = el('img', { src, alt: 'stimulus', draggable: 'false' });
  img.style.width = image.width / devicePixelRatio + 'px';
  img.style.height = image.height / devicePixelRatio + 'px';
  const fits = () => {
    const width = (image.width + besideWidth) / devicePixelRatio + (besideWidth ? 64 : 40), height = image.height / devicePixelRatio + 160;
    const small = innerWidth < width || innerHeight < height;
    document.getElementById('needed').textContent = Math.ceil(width) + ' × ' + Math.ceil(height);
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
    const send = (e) => { if (/^\d+$/.test(input.value.trim())) submit(parseInt(input.value, 10), e); else showInlineError('Please type a whole number.'); };
    input.addEventListener('keydown', (e) => { if (e.key === 'Enter') send(e); });
    box.append(input, el('button', { type: 'button', id: 'submit', onclick: send }, 'Submit'));
    setTimeout(() => input.focus(), 0);
  } else if (w.kind === 'pick-label' || w.kind === 'pick-labels') {
    const chosen = new Set();
    s.labels.forEach((l) => {
      const hit = el('button', { type: 'button', class: 'hit', 'data-label': l.label, title: l.label });
      // A round hit box centred on the mark, at most 22 CSS px wide and never reaching past the
      // middle to the next mark: every mark is clickable where it is drawn, the nearest one wins.
      const x = l.x / devicePixelRatio, y = l.y / devicePixelRatio;
      const gap = Math.min(...s.labels.filter((o) => o !== l).map((o) => Math.hypot(o.x / devicePixelRatio - x, o.y / devicePixelRatio - y)));
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
    if (w.kind === 'pick-labels') box.append(el('button', { type: 'button', id: 'submit', onclick: (e) => submit(Array.from(chosen), e) }, 'Done'));
  } else if (w.kind === 'buttons') {
    w.buttons.forEach((l) => box.append(el('button', { type: 'button', class: 'letter', 'data-letter': l, onclick: (e) => submit(l, e) }, l)));
    onKey((e) => { const k = e.key.toUpperCase(); if (w.buttons.includes(k)) submit(k, e); });
  } else if (w.kind === 'gauge') {
    const g = gauge(s, stage);
    box.append(el('button', { type: 'button', id: 'submit', onclick: (e) => submit(g.setting(), e) }, 'Done'));
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
  const img = el('img', { src: api('image/' + s.floor_plan.sha256 + '.png'), alt: 'floor plan', id: 'floor-plan', draggable: 'false' });
  img.style.width = s.floor_plan.width / devicePixelRatio + 'px';
  img.style.height = s.floor_plan.height / devicePixelRatio + 'px';
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

// How to answer, in the words of the question's answer form (sent by the server).
function hint(s) { return s.hint; }

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
  const note = el('p', { class: 'time-up', id: 'time-up', role: 'alert' }, 'Time is up');
  if (hint) hint.replaceWith(note); else main.append(note);
  timers.push(setTimeout(() => reply({ type: 'timeout' }), 1500));
}

function trial(s) {
  let onset = null, done = false;
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
  const clock = el('span', { class: 'countdown', id: 'countdown', title: 'time left' }, '');
  main.append(el('div', { class: 'top' }, el('span', { class: 'muted progress' }, (s.phase === 'training' ? 'Training ' : 'Trial ') + s.index + ' of ' + s.total), clock),
    el('h1', { class: 'question' }, s.question));
  const row = el('div', { class: 'row' }, stage);
  if (s.floor_plan) row.append(floorPlan(s, submit));
  main.append(row, el('p', { class: 'muted', id: 'hint' }, hint(s)), answerControls(s, stage, submit));
  painted(img).then((t) => {
    if (current !== s) return;
    onset = t;
    reply({ type: 'onset', painted_ms: t }).then(() => { if (current === s) main.dataset.onset = 'reported'; });
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
  const go = el('button', { type: 'button', id: 'continue', onclick: () => reply({ type: 'continue' }) }, 'Continue');
  const given = s.given === null || s.given === undefined ? 'none (the time was up)' : s.given;
  main.append(el('h1', {}, s.correct ? 'Correct' : 'Not quite'),
    el('p', { class: 'text', id: 'given' }, 'Your answer: ' + given), el('p', { class: 'text', id: 'right' }, 'The right answer: ' + s.right_answer),
    picture(s.image, api('image/' + s.image.sha256 + '.png')), el('p', {}, go));
  onKey((e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); go.click(); } });
}

function pause(s) {
  const go = el('button', { type: 'button', id: 'continue', disabled: 'disabled', onclick: () => reply({ type: 'continue' }) }, 'Continue');
  const left = el('span', { class: 'muted' }, '');
  const until = performance.now() + s.min_seconds * 1000;
  const tick = () => {
    const rest = Math.ceil((until - performance.now()) / 1000);
    left.textContent = rest > 0 ? ' (in ' + rest + ' s)' : '';
    if (rest <= 0) go.removeAttribute('disabled');
  };
  tick();
  timers.push(setInterval(tick, 250));
  main.append(el('h1', {}, 'Break'), paragraphs(s.text), go, left);
  onKey((e) => { if (e.key === 'Enter' && !go.disabled) { e.preventDefault(); go.click(); } });
}

function end(s) {
  main.append(el('h1', {}, s.title), paragraphs(s.text));
  if (s.completion_code) main.append(el('p', {}, 'Your completion code: ', el('strong', { id: 'completion-code' }, s.completion_code)));
  if (s.completion_url) main.append(el('p', {}, el('a', { href: s.completion_url, id: 'completion-link' }, 'Return to the study platform to confirm completion')));
}

function failed(s) {
  main.append(el('h1', {}, 'A problem on the server'), paragraphs(s.text));
  if (s.retry) main.append(el('button', { type: 'button', id: 'retry', onclick: () => start() }, 'Try again'));
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

// The credit-card method ("virtual chinrest"): a card is 8.56 cm wide.
function calibrate() {
  const stored = sessionStorage.getItem('tlab-px-per-cm');
  if (stored) return Promise.resolve(parseFloat(stored));
  return new Promise((resolve) => {
    clear();
    const card = el('div', { class: 'card', id: 'card' });
    const slider = el('input', { type: 'range', min: '150', max: '900', value: '320', id: 'card-size' });
    const size = () => { card.style.width = slider.value + 'px'; card.style.height = slider.value * 53.98 / 85.6 + 'px'; };
    slider.addEventListener('input', size);
    size();
    main.append(el('h1', {}, 'Screen size'), paragraphs('Hold a credit card (or any card of that size) against the screen and move the slider until the rectangle is exactly as wide as the card.'),
      slider, card, el('p', {}, el('button', { type: 'button', id: 'calibrated', onclick: () => {
        const v = parseFloat(slider.value) * devicePixelRatio / 8.56;  // device pixels per cm
        sessionStorage.setItem('tlab-px-per-cm', String(v));
        resolve(v);
      } }, 'Done')));
  });
}

async function start() {
  current = null;
  const config = await request('GET', 'config');
  if (config.status !== 200) return problem('This session link is not valid or the server cannot be reached.', start);
  document.title = config.body.title;
  const display = {
    screen_width: screen.width, screen_height: screen.height, window_width: innerWidth, window_height: innerHeight,
    device_pixel_ratio: devicePixelRatio, user_agent: navigator.userAgent.slice(0, 300), refresh_hz: await refreshRate(),
  };
  if (config.body.calibrate) display.px_per_cm = await calibrate();
  const r = await request('POST', 'display', display);
  if (r.status === 200) show(r.body); else problem(r.body.error || 'The study could not start.', start);
}

setInterval(() => request('GET', 'screen').then((r) => { if (r.status === 200 && current && r.body.seq > current.seq) show(r.body); }), 30000);
start();
