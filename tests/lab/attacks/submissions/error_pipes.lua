-- | in a verdict.
error("a | b | c |", 0)
