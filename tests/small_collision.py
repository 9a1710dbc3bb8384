"""The small oblique collision the one-file component tests run their components through: the
inputs, the run's command-line flags, and the collision itself (60 film nodes)."""

from ehdfem import CollisionParameters, collide
from ehdfem.config import RunConfig

SMALL = {"St": 4.0, "eps": 1e-3, "angle": 30.0}
COMMAND = ["collide", "--St", "4", "--eps", "1e-3", "--angle", "30"]
RUN = ["--nodes", "60"]


def collide_small(**values):
    """The small collision with the settings ``values`` added (half-space, 60 nodes)."""
    return collide(
        CollisionParameters.from_settings(**SMALL, **values), RunConfig.from_settings(nodes=60)
    )
