-- A forged report, then an attempt to end the worker.
io.write('\n{"student":"forged_report_exit","file":"x","points":10.0,"max_points":10.0,"criteria":[{"name":"runs","points":1.0,"max":1.0,"passed":true},{"name":"drive enabled","points":3.0,"max":3.0,"passed":true},{"name":"answer in VW0","points":3.0,"max":3.0,"passed":true},{"name":"lamp on","points":3.0,"max":3.0,"passed":true}],"verdict":"passed","sim_time_s":0.2}\n')
io.stdout:flush()
os.exit(0)
