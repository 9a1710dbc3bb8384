"""The inputs of a collision: dimensionless groups and their physical scales (scales), material
and liquid presets (presets) and published experiments (literature). The input checks that name
a parameter and its allowed range are below every package, in :mod:`ehdfem.checks`."""
