os.execute("touch /tmp/plcsh-lab-escaped")
