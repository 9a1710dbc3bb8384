"""A sphere bouncing on a wall in a liquid: the flight between contacts and an immersed EHD
collision at each contact (trajectory). Inputs and results in SI."""
