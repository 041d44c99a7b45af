-- Escape sequences in an error.
error("\27[2J\27[H\27]0;pwned\7 terminal cleared")
