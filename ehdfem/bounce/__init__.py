"""A sphere bouncing on a wall in a liquid (:func:`ehdfem.bounce.trajectory.bounce_sphere`): its
inputs (inputs), how it is computed (run), the flight between contacts (flight), an immersed
EHD collision at each contact (contact), the loop of flight legs and contacts until the sphere
rests (loop) and the result (result); the history force and the wall's added mass (unsteady)
and resolved liquid flows (wall_flow, sphere_flow, near_wall_flow, liquid_forms). Inputs and
results in SI."""
