"""`python -m paper` is the `appell` command."""

from paper.cli import main

raise SystemExit(main())
