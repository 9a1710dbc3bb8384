"""What a collision gives back: the registry of its outputs (registry), field files for
ParaView (fields), matplotlib plots (plots) and pyvista pictures (render)."""
