#!/usr/bin/env python3
"""A built MkDocs site renders its equations offline: every script and stylesheet a page loads is a file of the site
(none from another host: no CDN, no web fonts), MathJax's parts that the site's configuration loads are there, and
each page named on the command line holds equations marked for MathJax (pymdownx.arithmatex's class "arithmatex").

Usage: check_site_offline.py SITE_DIR [PAGE.html ...]
exit 0 when all holds, 1 naming each script, stylesheet, MathJax file or page that fails.
"""
import html.parser
import pathlib
import sys
import urllib.parse

# The files MathJax 2.7 reads to render TeX in CommonHTML (docs/javascripts/mathjax-config.js), under the site.
MATHJAX_FILES = [
    "javascripts/mathjax/MathJax.js",
    "javascripts/mathjax/config/TeX-AMS_CHTML.js",
    "javascripts/mathjax/jax/input/TeX/config.js",
    "javascripts/mathjax/jax/output/CommonHTML/jax.js",
    "javascripts/mathjax/jax/output/CommonHTML/fonts/TeX/fontdata.js",
    "javascripts/mathjax/fonts/HTML-CSS/TeX/woff/MathJax_Main-Regular.woff",
    "javascripts/mathjax/fonts/HTML-CSS/TeX/woff/MathJax_Math-Italic.woff",
]


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.loads, self.equations = [], 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "script" and a.get("src"):
            self.loads.append(a["src"])
        if tag == "link" and a.get("href") and "stylesheet" in (a.get("rel") or ""):
            self.loads.append(a["href"])
        if "arithmatex" in (a.get("class") or "").split():
            self.equations += 1


def problems_of(site, pages_with_equations):
    found = []
    for path in sorted(site.rglob("*.html")):
        page = Page()
        page.feed(path.read_text(encoding="utf-8", errors="replace"))
        name = path.relative_to(site).as_posix()
        for src in page.loads:
            url = urllib.parse.urlparse(src)
            if url.scheme or url.netloc:
                found.append(f"{name}: loads {src} from another host (the site must work offline)")
                continue
            # A path from the site's root (404.html's, which any folder may serve) or from the page's folder.
            base = site if url.path.startswith("/") else path.parent
            if not (base / urllib.parse.unquote(url.path).lstrip("/")).is_file():
                found.append(f"{name}: loads {src}, which the site lacks")
        if name in pages_with_equations and page.equations == 0:
            found.append(f"{name}: no equation marked for MathJax (class arithmatex)")
    for name in pages_with_equations:
        if not (site / name).is_file():
            found.append(f"{name}: no such page in the site")
    for name in MATHJAX_FILES:
        if not (site / name).is_file():
            found.append(f"{name}: missing (MathJax is copied in by scripts/mkdocs_mathjax.py)")
    return found


def main(argv):
    if len(argv) < 2:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    found = problems_of(pathlib.Path(argv[1]), argv[2:])
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
