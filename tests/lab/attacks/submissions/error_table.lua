-- An error that is a table (no address in the verdict).
error({})
