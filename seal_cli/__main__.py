"""``python -m seal_cli`` runs the ``seal`` command line."""

from seal_cli.cli import main

main()
