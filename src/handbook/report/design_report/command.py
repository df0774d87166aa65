"""``python -m handbook report SPEC.toml -o FILE.html|FILE.pdf``: the spec read and designed as ``design`` does
(the same messages and exit codes: 2 for a bad key or value, 3 when a table cannot be met, 4 when a PDF is asked
and no Chromium is installed), then the report written whole or not at all (a temporary file beside the target,
renamed)."""
from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

SUFFIXES = (".html", ".htm", ".pdf")


def _error(code: int, message: str) -> int:
    print(f"error: {message}", file=sys.stderr)
    return code


def _atomic(target: Path, write) -> None:
    """``write(tmp_path)`` fills a temporary file beside ``target``, which then replaces ``target``; on any error
    the temporary file is removed and ``target`` left as it was."""
    fd, tmp = tempfile.mkstemp(prefix=f".{target.stem}-", suffix=target.suffix, dir=target.parent)
    os.close(fd)
    try:
        write(Path(tmp))
        mask = os.umask(0o022)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)  # as an ordinary new file (mkstemp makes it private)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _pdf(html: str, tmp: Path, browser: str) -> None:
    from ..chromium import print_pdf

    with tempfile.TemporaryDirectory(prefix="handbook-report-") as work:
        src = Path(work) / "report.html"
        src.write_text(html, encoding="utf-8")
        stderr = print_pdf(src, tmp, browser, budget_ms=10_000, timeout=300)
    if not tmp.exists() or tmp.stat().st_size < 1000:
        raise RuntimeError(f"Chromium printed no PDF: {stderr[-1000:]}")


def _designed(args):
    """(spec, results) or an exit code, with ``design``'s messages."""
    from ...core import InputError
    from ...design import spec as specmod
    from ...design.solvers import Infeasible

    try:
        spec = specmod.load(args.spec)
        results = specmod.run_each(spec)
    except InputError as exc:
        return _error(2, str(exc))
    failed = {t: r for t, r in results.items() if isinstance(r, Infeasible)}
    for table, exc in failed.items():
        print(f"cannot be met [{table}]: {exc}", file=sys.stderr)
    if failed:
        print(f"report: not written ({', '.join(failed)} cannot be met): {args.out}", file=sys.stderr)
        return 3
    return spec, results


def run(args) -> int:
    """The ``report`` subcommand.

    Parameters
    ----------
    args : argparse.Namespace
        ``spec`` (the TOML file), ``out`` (FILE.html or FILE.pdf), ``no_spice``.

    Returns
    -------
    int
        0 written; 2 a bad spec or an output that cannot be written; 3 a table that cannot be met; 4 a PDF asked
        for with no Chromium on the machine.
    """
    target = Path(args.out)
    if target.suffix.lower() not in SUFFIXES:
        return _error(2, f"-o {args.out}: name the report FILE.html or FILE.pdf")
    if not target.parent.is_dir():
        return _error(2, f"-o {args.out}: the folder {target.parent} does not exist; nothing written")
    browser = None
    if target.suffix.lower() == ".pdf":
        from ..chromium import chromium

        browser = chromium()
        if browser is None:
            return _error(4, "a PDF needs Chromium (Debian's 'chromium' package); none is installed: "
                          "write -o FILE.html instead")
    got = _designed(args)
    if isinstance(got, int):
        return got
    from . import build, context

    html = build(context(*got, spec_file=Path(args.spec).name, no_spice=args.no_spice))
    try:
        if browser:
            _atomic(target, lambda tmp: _pdf(html, tmp, browser))
        else:
            _atomic(target, lambda tmp: tmp.write_text(html, encoding="utf-8"))
    except OSError as exc:
        return _error(2, f"cannot write {args.out}: {exc.strerror or exc}; nothing written")
    except RuntimeError as exc:
        return _error(4, f"{exc}; nothing written")
    print(target)
    return 0
