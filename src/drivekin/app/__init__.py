"""Programs built on drivekin: the demo and the command lines; not part of the library API."""
