"""drivekin internals: C types and kernels, argument rules, value glue, the drivetrain
contract and the catalog. Nothing here is public API."""
