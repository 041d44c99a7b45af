-- Reading the environment.
error(tostring(os.getenv("HOME")), 0)
