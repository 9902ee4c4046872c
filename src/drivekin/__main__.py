"""``python -m drivekin``: runs :func:`drivekin.app.cli.main` (the demo and ``replay``)."""
import sys

from drivekin.app.cli import main

if __name__ == "__main__":
    sys.exit(main())
