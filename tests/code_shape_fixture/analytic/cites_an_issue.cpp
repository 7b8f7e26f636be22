// A code-shape fixture: a comment that cites a tracker issue by number (tests/code_shape.py must name it).
int cited() { return 12; }  // the bound of issue 12
