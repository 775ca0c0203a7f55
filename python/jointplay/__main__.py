"""``python -m jointplay``: the ``jointplay`` command."""

from jointplay.cli import main

main()
