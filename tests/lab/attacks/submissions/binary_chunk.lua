-- Bytecode.
assert(load(string.dump(function() end)))()
