#!/usr/bin/env python3
"""An executed notebook as a page of the site: its Markdown cells as they are, its code cells as ```python blocks,
their printed output as ```text blocks, and their figures (PNG) as files beside the page, linked from it.

    PYTHONPATH=build/python /usr/bin/python3 scripts/notebook_page.py [--execute] [--check]
        [--notebook docs/notebooks/first-steps.ipynb] [--page docs/tutorials/first-steps.md] [--label NAME]

--execute runs the notebook first (nbclient, Debian python3-nbclient and python3-ipykernel) and writes it back with
its outputs, from the repository's top folder.

The page is a function of the notebook alone (no date, no kernel's name, no folder it is read from: its header names
the notebook by --label, by default its path in the repository), so --check, which compares the committed
page and figures with what the notebook gives and names each that differs, holds them to the notebook
(python/tests/test_notebook.py). Apart from --execute only the standard library: the notebook is JSON (nbformat 4)."""

import argparse
import base64
import json
import pathlib
import sys

REPO = pathlib.Path(__file__).resolve().parents[1]
EXECUTE_TIMEOUT_S = 120  # per cell; the whole notebook runs in seconds
HEADER = ("<!-- Written by scripts/notebook_page.py from {notebook}: edit and re-run the notebook, then the script. "
          "-->\n\n")


def _text(value):
    return "".join(value) if isinstance(value, list) else value


def _outputs(cell, figures, stem):
    """A code cell's outputs as Markdown, the figures added to figures as {name: PNG bytes}."""
    parts = []
    for output in cell.get("outputs", []):
        kind = output["output_type"]
        if kind == "stream":
            parts.append(("text", _text(output["text"])))
        elif kind in ("execute_result", "display_data"):
            data = output["data"]
            if "image/png" in data:
                name = f"{stem}-{len(figures) + 1}.png"
                figures[name] = base64.b64decode(_text(data["image/png"]))
                parts.append(("figure", name))
            elif "text/plain" in data:
                parts.append(("text", _text(data["text/plain"]) + "\n"))
        elif kind == "error":
            raise SystemExit(f"notebook_page: a cell failed ({output['ename']}: {output['evalue']}); fix the notebook")
    blocks, text = [], ""
    for kind, value in parts + [("end", None)]:  # consecutive text outputs (prints, a result) as one block
        if kind == "text":
            text += value
            continue
        if text:
            lines = [line.rstrip() for line in text.rstrip("\n").split("\n")]  # a table's padding: no trailing blanks
            blocks.append("```text\n" + "\n".join(lines) + "\n```\n")
            text = ""
        if kind == "figure":
            blocks.append(f"![Figure {value.rsplit('-', 1)[1].split('.')[0]} of the notebook]({stem}/{value})\n")
    return blocks


def label_of(notebook_path):
    """The notebook's name in the page's header: its path in the repository, so the page does not depend on the
    folder the script runs from; a notebook outside the repository by its path as given."""
    path = pathlib.Path(notebook_path).resolve()
    return path.relative_to(REPO).as_posix() if path.is_relative_to(REPO) else pathlib.Path(notebook_path).as_posix()


def render(notebook_path, page_path, label):
    """The page's Markdown and its figures {file name: bytes} from the executed notebook, named label in the header."""
    notebook = json.loads(pathlib.Path(notebook_path).read_text(encoding="utf-8"))
    stem = pathlib.Path(page_path).stem
    figures, blocks = {}, [HEADER.format(notebook=label)]
    for cell in notebook["cells"]:
        source = _text(cell["source"]).rstrip("\n")
        if cell["cell_type"] == "markdown":
            blocks.append(source + "\n")
        elif cell["cell_type"] == "code" and source:
            blocks.append("```python\n" + source + "\n```\n")
            blocks += _outputs(cell, figures, stem)
    return "\n".join(blocks), figures


def execute(notebook_path):
    """Run the notebook from the repository's top folder and write it back with its outputs."""
    import nbclient
    import nbformat

    notebook = nbformat.read(notebook_path, as_version=4)
    nbclient.NotebookClient(notebook, timeout=EXECUTE_TIMEOUT_S, kernel_name="python3",
                            resources={"metadata": {"path": "."}}).execute()
    nbformat.write(notebook, notebook_path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--notebook", default="docs/notebooks/first-steps.ipynb")
    parser.add_argument("--page", default="docs/tutorials/first-steps.md")
    parser.add_argument("--label", help="the notebook's name in the page's header (default: its path in the "
                        "repository)")
    parser.add_argument("--check", action="store_true", help="compare with the committed page; write nothing")
    parser.add_argument("--execute", action="store_true", help="run the notebook and store its outputs first")
    args = parser.parse_args()
    if args.execute:
        execute(args.notebook)
    page = pathlib.Path(args.page)
    folder = page.parent / page.stem
    text, figures = render(args.notebook, page, args.label or label_of(args.notebook))
    wanted = {page: text.encode("utf-8"), **{folder / name: data for name, data in figures.items()}}
    if args.check:
        stale = [str(p) for p, data in wanted.items() if not p.is_file() or p.read_bytes() != data]
        extra = [str(p) for p in folder.glob("*") if p not in wanted] if folder.is_dir() else []
        for p in stale + extra:
            print(f"notebook_page: {p} is not what {args.notebook} gives (run scripts/notebook_page.py)",
                  file=sys.stderr)
        return 1 if stale or extra else 0
    folder.mkdir(parents=True, exist_ok=True)
    for p in folder.glob("*.png"):
        if p not in wanted:
            p.unlink()
    for p, data in wanted.items():
        p.write_bytes(data)
    return 0


if __name__ == "__main__":
    sys.exit(main())
