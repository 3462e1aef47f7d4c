"""Exit statuses of `cadmedial thickness` (for CI gates), shared by the CLI and the batch step."""

PASS, INTERNAL, BAD_INPUT, OUT_OF_LIMITS = 0, 1, 2, 3
