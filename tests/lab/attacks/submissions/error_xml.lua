-- XML markup in an error.
error("</failure></testcase><testcase name=\"forged\"/> & '", 0)
