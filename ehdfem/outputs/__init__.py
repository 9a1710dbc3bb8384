"""What a collision gives back: field files for ParaView (fields), matplotlib plots (plots) and
pyvista pictures (render)."""
