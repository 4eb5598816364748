#!/usr/bin/env python3
"""The built site, page by page, in headless Chromium (Debian's chromium package).

Every page of html/ is opened; the test fails on a formula MathJax left untypeset or could
not typeset, an image or figure that does not load, a link to a file or anchor that does not
exist or lies outside html/, a console error, an uncaught exception or a resource that
failed to load. Chapter pages must link to the previous and next chapter in the order of
chapters/CHAPTERS, and each must hold a motion player of all its scenes that loads, plays,
pauses, scrubs and changes speed with its cursor in step (motion_player_check.py). A screenshot of the main page and of every chapter page is kept in
SCREENSHOTS (a build artefact, to be looked at).

    python3 -m tests.site.test_site --html build/dev/book/site/html --screenshots build/dev/book/site/screenshots"""
import argparse
import html as html_text
import json
import pathlib
import re
import sys
import tempfile
import unittest
import urllib.parse

from docs import finish_site
from tests.site import browser, motion_player_check
from tools import workbook_files

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]

ARGS = None

WAIT_FOR_MATHJAX = """new Promise((resolve) => {
  const start = Date.now();
  (function wait() {
    if (window.MathJax && MathJax.Hub && MathJax.Hub.Queue) MathJax.Hub.Queue(() => resolve(true));
    else if (Date.now() - start > 30000) resolve(false);
    else setTimeout(wait, 50);
  })();
})"""

# What a reader would see wrong: formulas left as TeX or marked as errors, images and figures
# that did not load. Text inside code and scripts may quote TeX on purpose.
PAGE_PROBLEMS = r"""(() => {
  const bad = [];
  document.querySelectorAll('.MathJax_Error, .merror, .MathJax_Display .noError').forEach(
    e => bad.push('formula not typeset (MathJax error): ' + e.textContent.trim().slice(0, 100)));
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  while (walker.nextNode()) {
    const node = walker.currentNode;
    if (node.parentElement.closest('script, pre, code, .fragment, .MathJax_Preview, style')) continue;
    if (/\\f[$\[]|\\\(|\\\[|\\begin\{/.test(node.textContent))
      bad.push('formula left untypeset: ' + node.textContent.trim().slice(0, 100));
  }
  for (const image of document.images)
    if (!image.complete || image.naturalWidth === 0) bad.push('image did not load: ' + image.getAttribute('src'));
  for (const object of document.querySelectorAll('object')) {
    const doc = object.contentDocument;
    if (!doc || !doc.documentElement || doc.documentElement.nodeName.toLowerCase() !== 'svg')
      bad.push('figure did not load: ' + object.getAttribute('data'));
  }
  return bad;
})()"""

CHAPTER_NAV = """(() => {
  const nav = document.querySelector('nav.chapter-nav');
  if (!nav) return null;
  const href = (cls) => { const a = nav.querySelector('a.' + cls); return a ? a.getAttribute('href') : null; };
  return {prev: href('chapter-prev'), next: href('chapter-next'), index: href('chapter-index')};
})()"""

LINK = re.compile(r"""<(?:a|link|script|img|object|iframe)\b[^>]*?\b(?:href|src|data)\s*=\s*["']([^"']+)["']""", re.I)


def anchors(page):
    text = page.read_text(errors="replace")
    return set(re.findall(r"""\b(?:id|name)\s*=\s*["']([^"']+)["']""", text))


def broken_links(html_dir, page, anchor_cache):
    """Links of `page` to files or anchors that do not exist, or that leave html/."""
    problems = []
    root = html_dir.resolve()
    for raw in LINK.findall(page.read_text(errors="replace")):
        target = html_text.unescape(raw)
        scheme = urllib.parse.urlsplit(target).scheme
        if scheme in ("http", "https", "mailto", "javascript", "data") or target.startswith("#") and not target[1:]:
            continue
        parts = urllib.parse.urlsplit(target)
        path = urllib.parse.unquote(parts.path)
        file = (page.parent / path).resolve() if path else page.resolve()
        if root != file and root not in file.parents:
            problems.append(f"link leaves html/: {target}")
            continue
        if not file.exists():
            problems.append(f"broken link: {target}")
            continue
        if parts.fragment and file.suffix == ".html":
            if file not in anchor_cache:
                anchor_cache[file] = anchors(file)
            if parts.fragment not in anchor_cache[file]:
                problems.append(f"broken link (no anchor #{parts.fragment} in {file.name}): {target}")
    return problems


def chapter_pages(html_dir):
    """[(chapter id, page)] in the order of chapters/CHAPTERS, for the pages that were built."""
    return [(c, html_dir / finish_site.page_file(c)) for c in workbook_files.chapters(ROOT)
            if (html_dir / finish_site.page_file(c)).is_file()]


class SiteInBrowser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        executable = browser.find_chromium()
        if executable is None:
            raise RuntimeError("no Chromium to open the site with (Debian: apt install chromium; ./workbook setup installs it)")
        cls.html = ARGS.html.resolve()
        cls.screens = ARGS.screenshots.resolve()
        cls.screens.mkdir(parents=True, exist_ok=True)
        cls.browser = browser.Browser(executable)

    @classmethod
    def tearDownClass(cls):
        cls.browser.close()

    def test_every_page_loads_cleanly(self):
        pages = sorted(self.html.glob("*.html"))
        self.assertGreater(len(pages), 5, f"no site in {self.html}")
        shot = {"index.html"} | {p.name for _, p in chapter_pages(self.html)}
        anchor_cache = {}
        failures = []
        for page in pages:
            problems = self.browser.open(page.as_uri())
            if "MathJax.js" in page.read_text(errors="replace"):
                if not self.browser.evaluate(WAIT_FOR_MATHJAX):
                    problems.append("MathJax did not start")
            problems += self.browser.evaluate(PAGE_PROBLEMS)
            problems += self.browser.problems()  # anything reported while MathJax worked
            problems += broken_links(self.html, page, anchor_cache)
            if page.name in shot:
                # MathJax's "Typesetting math: 100%" box fades out a moment after it finishes.
                self.browser.evaluate("new Promise(r => setTimeout(r, 1500))")
                self.browser.screenshot(self.screens / (page.stem + ".png"))
            failures += [f"{page.name}: {p}" for p in dict.fromkeys(problems)]
        self.assertFalse(failures, "\n" + "\n".join(failures[:40]))
        for name in shot:
            self.assertTrue((self.screens / name.replace(".html", ".png")).stat().st_size > 10000, name)

    def test_chapter_pages_link_previous_and_next(self):
        chapters = chapter_pages(self.html)
        self.assertTrue(chapters, "no chapter pages")
        for i, (chapter, page) in enumerate(chapters):
            self.browser.open(page.as_uri())
            nav = self.browser.evaluate(CHAPTER_NAV)
            self.assertIsNotNone(nav, f"{page.name} has no chapter navigation")
            self.assertEqual(nav["prev"], chapters[i - 1][1].name if i > 0 else None, chapter)
            self.assertEqual(nav["next"], chapters[i + 1][1].name if i + 1 < len(chapters) else None, chapter)
            self.assertEqual(nav["index"], "index.html")

    def test_every_chapter_page_has_a_working_motion_player(self):
        """Plays, pauses, scrubs and changes speed on each chapter's player, with the cursor on
        the chapter's own figure in step (motion_player_check.py)."""
        chapters = chapter_pages(self.html)
        self.assertTrue(chapters, "no chapter pages")
        failures = []
        for chapter, page in chapters:
            titles = [json.loads(scene.read_text())["title"]
                      for scene in sorted((ROOT / "chapters" / chapter / "scenes").glob("*.json"))]
            problems = self.browser.open(page.as_uri())
            problems += motion_player_check.check(self.browser, titles)
            failures += [f"{page.name}: {p}" for p in problems]
        self.assertFalse(failures, "\n" + "\n".join(failures[:40]))

    def test_mathjax_is_inside_the_site(self):
        mathjax = self.html / "mathjax"
        self.assertTrue((mathjax / "MathJax.js").is_file())
        self.assertFalse(mathjax.is_symlink(), "MathJax is a link: the site breaks when copied elsewhere")


class ChapterNavigation(unittest.TestCase):
    """finish_site.py's links, for a book of three chapters (no browser needed)."""

    def test_three_chapters_link_in_order(self):
        with tempfile.TemporaryDirectory() as scratch:
            folder = pathlib.Path(scratch)
            chapters = ["inelastic", "projection", "linear-impulse"]
            for n, chapter in enumerate(chapters, 1):
                (folder / finish_site.page_file(chapter)).write_text(
                    f'<div class="title">Chapter {n} title</div><div class="contents"><div class="textblock">text'
                    '</div></div><!-- contents -->')
            self.assertEqual(finish_site.add_navigation(folder, chapters), 3)
            middle = (folder / "chapter_projection.html").read_text()
            self.assertIn('href="chapter_inelastic.html">← Chapter 1 · Chapter 1 title</a>', middle)
            self.assertIn('href="chapter_linear_impulse.html">Chapter 3 · Chapter 3 title</a>', middle)
            # A page titled "Chapter N · Title", as every chapter page is, is not labelled twice.
            (folder / finish_site.page_file("linear-impulse")).write_text(
                '<div class="title">Chapter 3 · Bounces</div><div class="contents"><div class="textblock">text'
                '</div></div><!-- contents -->')
            (folder / "chapter_projection.html").write_text(
                '<div class="title">Chapter 2 · Middle</div><div class="contents"><div class="textblock">text'
                '</div></div><!-- contents -->')
            finish_site.add_navigation(folder, chapters)
            self.assertIn('href="chapter_linear_impulse.html">Chapter 3 · Bounces</a>',
                          (folder / "chapter_projection.html").read_text())
            self.assertLess(middle.index("chapter-nav"), middle.index("</div></div><!-- contents -->"))
            first = (folder / "chapter_inelastic.html").read_text()
            self.assertNotIn("chapter-prev\" href", first)
            self.assertEqual(finish_site.add_navigation(folder, chapters), 3)  # a second run adds nothing
            self.assertEqual((folder / "chapter_projection.html").read_text().count("chapter-nav\""), 1)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--html", type=pathlib.Path, required=True)
    parser.add_argument("--screenshots", type=pathlib.Path, required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
