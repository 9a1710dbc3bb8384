"""The suite computes every FE compliance (EHDFEM_COMPLIANCE_CACHE=off, also for the commands
it runs): a cached matrix would let a test on 2 ranks read what 1 rank computed. The cache has
its own test (tests/test_fem.py)."""

import os

os.environ["EHDFEM_COMPLIANCE_CACHE"] = "off"
