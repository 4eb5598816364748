#!/usr/bin/env python3
"""Finishes the site Doxygen wrote, so that html/ stands on its own (a zip, a web server):

- copies the part of MathJax 2 the pages load (TeX input, HTML-CSS output, the TeX web
  fonts) into html/mathjax/, or links it there with --link-mathjax for a quick local build;
- gives every chapter page previous and next links, in the order of chapters/CHAPTERS, so a
  reader can go through the book page by page. A chapter added to CHAPTERS gets them too.

    python3 -m docs.finish_site HTML_DIR --mathjax /usr/share/javascript/mathjax [--link-mathjax]"""
import argparse
import html
import os
import pathlib
import re
import shutil

from tools import workbook_files

ROOT = pathlib.Path(__file__).resolve().parents[1]

# What Doxygen's MathJax 2 configuration (TeX/AMSmath, TeX/AMSsymbols, output/HTML-CSS) loads.
MATHJAX_PARTS = ["MathJax.js", "extensions", "jax/element", "jax/input/TeX", "jax/output/HTML-CSS/config.js",
                 "jax/output/HTML-CSS/jax.js", "jax/output/HTML-CSS/imageFonts.js", "jax/output/HTML-CSS/autoload",
                 "jax/output/HTML-CSS/fonts/TeX", "fonts/HTML-CSS/TeX/woff", "fonts/HTML-CSS/TeX/otf"]
NAV_MARK = "<!-- workbook chapter navigation -->"


def install_mathjax(source, target, link):
    if target.is_symlink() or target.is_file():
        target.unlink()
    elif target.exists():
        shutil.rmtree(target)
    if link:
        target.symlink_to(source, target_is_directory=True)
        return
    for part in MATHJAX_PARTS:
        src = source / part
        if not src.exists():
            raise SystemExit(f"finish_site.py: MathJax at {source} has no {part}")
        dst = target / part
        dst.parent.mkdir(parents=True, exist_ok=True)
        if src.is_dir():
            shutil.copytree(src, dst, symlinks=False)
        else:
            shutil.copy2(src, dst)


def page_file(chapter):
    return "chapter_" + chapter.replace("-", "_") + ".html"


def page_title(path):
    match = re.search(r'<div class="title">(.*?)</div>', path.read_text(errors="replace"), re.S)
    return re.sub(r"<[^>]+>", "", match.group(1)).strip() if match else path.stem


def nav_html(number, previous, following):
    """The navigation block: previous chapter on the left, next on the right, titles linked."""
    def link(target, label, cls):
        if target is None:
            return f'<span class="{cls}"></span>'
        (n, file, title) = target
        # Chapter pages are titled "Chapter N · Title"; the label is not said twice.
        title = re.sub(rf"^Chapter {n}\s*·\s*", "", title)
        return f'<a class="{cls}" href="{file}">{label} {n} · {html.escape(title)}</a>'

    return (f'{NAV_MARK}<nav class="chapter-nav" aria-label="chapters">'
            f'{link(previous, "← Chapter", "chapter-prev")}'
            f'<a class="chapter-index" href="index.html">Contents</a>'
            f'{link(following, "Chapter", "chapter-next")}</nav>\n'
            '<style>.chapter-nav{display:flex;justify-content:space-between;gap:1em;margin:2em 0 1em;'
            'padding-top:.8em;border-top:1px solid var(--separator-color,#ddd)}'
            '.chapter-nav a{text-decoration:none}a.chapter-next::after{content:" →"}</style>\n')


def add_navigation(html_dir, chapters):
    pages = [(n, page_file(c)) for n, c in enumerate(chapters, 1) if (html_dir / page_file(c)).is_file()]
    titled = [(n, file, page_title(html_dir / file)) for n, file in pages]
    for i, (n, file, _) in enumerate(titled):
        path = html_dir / file
        text = path.read_text(errors="replace")
        if NAV_MARK in text:
            continue
        block = nav_html(n, titled[i - 1] if i > 0 else None, titled[i + 1] if i + 1 < len(titled) else None)
        # At the end of the page's text block (doxygen-awesome lays the contents out as a row
        # of text and table of contents, so the links go inside the text), else of its contents.
        at = text.rfind("</div></div><!-- contents -->")
        if at < 0:
            at = text.rfind("</div><!-- contents -->")
        if at < 0:
            raise SystemExit(f"finish_site.py: {file} has no end of contents to put the chapter links at")
        path.write_text(text[:at] + block + text[at:])
    return len(titled)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("html", type=pathlib.Path, help="the html/ folder Doxygen wrote")
    parser.add_argument("--mathjax", type=pathlib.Path, required=True, help="MathJax 2's folder")
    parser.add_argument("--link-mathjax", action="store_true", help="link MathJax instead of copying it")
    args = parser.parse_args()
    install_mathjax(args.mathjax.resolve(), args.html / "mathjax", args.link_mathjax)
    count = add_navigation(args.html, workbook_files.chapters(ROOT))
    print(f"Site finished: MathJax {'linked' if args.link_mathjax else 'copied'} into html/mathjax, "
          f"previous/next links on {count} chapter page(s)")


if __name__ == "__main__":
    main()
