"""The motion player of a page, checked in the browser (plots/motion-player.js).

One check, used by the site's browser test on every chapter page (tests/site/test_site.py)
and by tests/motion/player_test.py on a page built from one chapter's figures alone:

- it loads: every scene of the chapter is in its menu, each with its chapter figure (the
  image loads, one cursor per panel of the figure);
- it plays: after the play button, the time shown grows and every cursor stands where that
  time lies on its panel's axis (from the figure's own panel positions), inside the plot;
- pause holds the time; scrubbing to the middle of the bar shows the middle of the scene,
  with the cursors there; the cursors reach both ends of the axes at 0 and at the end;
- speed: at 2x, one second of the clock advances 2 / (slow-motion factor) seconds of the
  scene, exactly, and the text beside the menu says so;
- nothing is fetched from the network: every resource the page loaded is a local file.

check(browser) returns a list of problems as sentences (empty when the player works).
"""

CHECK = r"""(async () => {
  const bad = [];
  const sleep = (ms) => new Promise(r => setTimeout(r, ms));
  const roots = document.querySelectorAll('.wb-motion');
  if (roots.length !== 1) return {bad: [roots.length + ' players on the page, expected 1'], scenes: []};
  const root = roots[0], p = root.wbPlayer;
  if (!p) return {bad: ['the player did not start: ' + root.textContent.slice(0, 200)], scenes: []};
  const figures = window.WorkbookMotionFigures || {};
  const close = (a, b, scale) => Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(scale));
  const where = (f, panel, t) => {
    const u = Math.max(0, Math.min(1, (t * f.x_per_second - panel.x0) / (panel.x1 - panel.x0)));
    return panel.left + u * (panel.right - panel.left);
  };
  // Cursors at time t: each on its panel, inside the plot area, where t lies on the axis.
  const cursorsAt = (what, t) => {
    const f = figures[p.scene.chapter + '/' + p.scene.scene];
    const lines = root.querySelectorAll('.wb-figure .wb-cursor');
    if (!f) { bad.push(p.scene.scene + ': no figure data'); return; }
    if (lines.length !== f.panels.length) bad.push(p.scene.scene + ': ' + lines.length + ' cursors for ' + f.panels.length + ' panels');
    lines.forEach((line, n) => {
      const panel = f.panels[n], x = +line.getAttribute('x1');
      if (!close(x, where(f, panel, t), panel.right))
        bad.push(`${p.scene.scene} ${what}: cursor ${n} at x = ${x}, the time ${t} s lies at ${where(f, panel, t)}`);
      if (x < panel.left - 1e-9 || x > panel.right + 1e-9 || +line.getAttribute('y1') !== panel.top || +line.getAttribute('y2') !== panel.bottom)
        bad.push(`${p.scene.scene} ${what}: cursor ${n} leaves the plot area`);
    });
  };
  const time = () => +root.getAttribute('data-time');
  const imageLoaded = async () => {
    const img = root.querySelector('.wb-figure img');
    if (!img) return false;
    for (let i = 0; i < 100 && !img.complete; i++) await sleep(20);
    return img.complete && img.naturalWidth > 0;
  };

  // Loads: every scene, with its figure and cursors at 0 and at the end.
  const scenes = Array.from(p.select.options).map(o => o.textContent);
  for (let i = 0; i < p.select.options.length; i++) {
    p.select.value = String(i);
    p.select.dispatchEvent(new Event('change'));
    if (!(await imageLoaded())) bad.push(p.scene.scene + ': its figure did not load');
    cursorsAt('at the start', 0);
    p.show(p.scene.duration);
    cursorsAt('at the end', p.scene.duration);
    const f = figures[p.scene.chapter + '/' + p.scene.scene];
    if (f && f.panels.some(panel => !close(where(f, panel, p.scene.duration), panel.right, panel.right)))
      bad.push(p.scene.scene + ': the figure\'s time axis does not end at the scene\'s duration');
  }
  p.select.value = '0';
  p.select.dispatchEvent(new Event('change'));

  // Plays (real clock), then pauses.
  const play = root.querySelector('.wb-play');
  play.click();
  if (root.getAttribute('data-playing') !== 'true') bad.push('the play button did not start playing');
  await sleep(600);
  play.click();
  const played = time();
  if (!(played > 0)) bad.push('after 0.6 s of playing the time is still ' + played + ' s');
  cursorsAt('after playing', played);
  await sleep(200);
  if (root.getAttribute('data-playing') !== 'false' || time() !== played) bad.push('pause did not hold the time');

  // Scrubbing to the middle of the bar.
  const bar = root.querySelector('.wb-scrub');
  bar.value = String((+bar.max) / 2);
  bar.dispatchEvent(new Event('input'));
  if (!close(time(), p.scene.duration / 2, p.scene.duration)) bad.push(`scrubbed to the middle, the time is ${time()} s of ${p.scene.duration} s`);
  cursorsAt('scrubbed', time());

  // Speed: 2x, one clock second, exactly.
  const speed = root.querySelector('.wb-speed');
  speed.value = '2';
  speed.dispatchEvent(new Event('change'));
  const factor = p.scene.slow_motion / 2;
  const said = root.querySelector('.wb-speed-text').textContent;
  const expected = factor === 1 ? 'real time' : factor > 1 ? 'slow motion ×' + (+factor.toPrecision(4)) : 'fast motion ×' + (+(1 / factor).toPrecision(4));
  if (!said.includes(expected)) bad.push(`at 2× the player says "${said}", expected "${expected}"`);
  p.show(0);
  p.play();
  p.last = 0;
  p.tick(1000);
  p.pause();
  const want = Math.min(2 / p.scene.slow_motion, p.scene.duration);
  if (!close(time(), want, p.scene.duration)) bad.push(`at 2× one second of play advanced ${time()} s, expected ${want} s`);
  cursorsAt('at 2×', time());
  speed.value = '1';
  speed.dispatchEvent(new Event('change'));

  // Offline: everything the page loaded is a local file.
  performance.getEntriesByType('resource').forEach(e => {
    if (!e.name.startsWith('file:')) bad.push('fetched from outside the site: ' + e.name);
  });
  return {bad: bad, scenes: scenes};
})()"""


def check(browser, scene_titles=None):
    """Problems of the player on the page open in `browser`; with `scene_titles`, the menu
    must hold exactly those scenes (in any order)."""
    result = browser.evaluate(CHECK)
    problems = list(result["bad"])
    if scene_titles is not None and sorted(result["scenes"]) != sorted(scene_titles):
        problems.append(f"the scene menu lists {sorted(result['scenes'])}, the chapter has {sorted(scene_titles)}")
    return problems
