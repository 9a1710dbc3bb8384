"""Around a run, not part of the physics: progress bars (progress) and the form compiler's and
VTK's output kept quiet (quiet)."""
