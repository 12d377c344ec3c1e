"""``python -m seal_cli`` runs the ``seal`` command line."""

from .cli import main

main()
