// MathJax 2.7 (Debian's libjs-mathjax, copied into the site by scripts/mkdocs_mathjax.py), configured before
// MathJax.js loads: the TeX input and CommonHTML output, reading only what pymdownx.arithmatex marked (its generic
// mode: \( \) inline, \[ \] displayed, inside elements of class "arithmatex"), so that a dollar sign or a backslash
// in prose or code is left alone.
window.MathJax = {
  config: ["TeX-AMS_CHTML.js"],
  tex2jax: {
    inlineMath: [["\\(", "\\)"]],
    displayMath: [["\\[", "\\]"]],
    processEscapes: true,
    processEnvironments: true,
    ignoreClass: ".*|",
    processClass: "arithmatex"
  },
  // No "Loading" box in the corner. (Automatic line breaks stay off: with them MathJax 2.7 gave a processing error
  // on every equation of docs/model/analytic-core.md; the theme scrolls a wide equation sideways instead.)
  showProcessingMessages: false,
  messageStyle: "none"
};
