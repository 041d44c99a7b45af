-- NUL and other C0 characters in an error.
error("nul\0here \1\2\31 \127", 0)
