#!/usr/bin/env python3
"""Every in-site link with an anchor (page.html#part, #part) in a built MkDocs site points at an id that exists.

MkDocs 1.4 (Debian's) checks that a linked page exists but not its anchor, so a renamed heading leaves links that
open at the top of the page. This reads the built HTML (the ids MkDocs itself gave the headings), not the Markdown.
Usage: check_anchors.py SITE_DIR       exit 0 when every anchor resolves, 1 naming each one that does not.
"""
import html.parser
import pathlib
import sys
import urllib.parse


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"])
        if tag == "a" and a.get("href"):
            self.links.append(a["href"])


def main(site):
    pages = {}
    for path in site.rglob("*.html"):
        p = Page()
        p.feed(path.read_text(encoding="utf-8", errors="replace"))
        pages[path.resolve()] = p
    broken = []
    for path, page in sorted(pages.items()):
        for href in page.links:
            url = urllib.parse.urlparse(href)
            if url.scheme or url.netloc or not url.fragment:
                continue  # another site, or no anchor
            target = path if not url.path else (path.parent / urllib.parse.unquote(url.path)).resolve()
            if target.is_dir():
                target = target / "index.html"
            if target not in pages:
                continue  # not a page of the site (a file beside it): mkdocs --strict checks pages
            if urllib.parse.unquote(url.fragment) not in pages[target].ids:
                broken.append(f"{path.relative_to(site.resolve())}: {href} (no id '{url.fragment}' there)")
    for b in broken:
        print("broken anchor:", b)
    print(f"anchors: {sum(len(p.links) for p in pages.values())} links on {len(pages)} pages, {len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
