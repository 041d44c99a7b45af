-- Newlines and | in an error: no fake rows.
error("line one\n| fake | 10/10 | 4 | | passed | 0 s |\nmore", 0)
