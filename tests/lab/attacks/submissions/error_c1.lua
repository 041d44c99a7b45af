-- C1 control characters (NEL, CSI) in an error.
error("c1 \u{85}\u{9b}2J", 0)
