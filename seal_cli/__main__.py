"""The entry point of ``seal`` and ``python -m seal_cli``.

``seal --version`` is answered here, before the command line's framework is imported: typer alone
costs about five times a bare interpreter's start-up (measured by ``seal bench startup``), and a
version check should cost nothing. Everything else goes to :data:`seal_cli.cli.app`.
"""

from __future__ import annotations

import sys


def main() -> None:
    if sys.argv[1:] == ["--version"]:
        from seal_cli import __version__

        sys.stdout.write(f"seal {__version__}\n")
        return
    from seal_cli.cli import main as run

    run()


if __name__ == "__main__":
    main()
