"""Parameter studies: sweeps over MPI ranks with resumable result tables and the critical Stokes
number (sweep)."""
