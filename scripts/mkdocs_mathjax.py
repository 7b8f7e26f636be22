"""An MkDocs hook (mkdocs.yml `hooks:`): the equations' MathJax, copied from Debian's libjs-mathjax into the built
site, so that the site renders its equations offline (no CDN).

Only the part of MathJax 2.7 the site loads is copied (about 1.3 MB of the package's 40 MB): MathJax.js, the
TeX-AMS_CHTML combined configuration, the TeX input, the CommonHTML output with its font metrics, the MathML element
jax, the extensions (TeX ones load on demand, e.g. \\boldsymbol) and the TeX web fonts (woff; otf for browsers
without woff). docs/javascripts/mathjax-config.js tells MathJax to read only what pymdownx.arithmatex marked.
"""
import pathlib
import shutil

from mkdocs.exceptions import PluginError

# Where Debian's libjs-mathjax installs MathJax (scripts/setup.sh installs the package).
MATHJAX = pathlib.Path("/usr/share/javascript/mathjax")
# The site's copy, the folder mkdocs.yml's extra_javascript loads MathJax.js from.
SITE_FOLDER = "javascripts/mathjax"
# What the site loads, relative to MATHJAX.
PARTS = [
    "MathJax.js",
    "config/TeX-AMS_CHTML.js",
    "jax/input/TeX",
    "jax/output/CommonHTML",
    "jax/element/mml",
    "extensions",
    "fonts/HTML-CSS/TeX/woff",
    "fonts/HTML-CSS/TeX/otf",
]


def on_post_build(config, **kwargs):
    if not (MATHJAX / "MathJax.js").is_file():
        raise PluginError(f"MathJax is not installed ({MATHJAX}/MathJax.js is missing): the site's equations need "
                          "Debian's libjs-mathjax (bash scripts/setup.sh installs it)")
    target = pathlib.Path(config["site_dir"]) / SITE_FOLDER
    for part in PARTS:
        source = MATHJAX / part
        if not source.exists():
            raise PluginError(f"MathJax's {source} is missing: the libjs-mathjax package is not the 2.7 this site "
                              "was written for")
        # Debian's files may be symbolic links into fonts-mathjax: the site gets the files themselves.
        if source.is_dir():
            shutil.copytree(source, target / part, dirs_exist_ok=True)
        else:
            (target / part).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source, target / part)
