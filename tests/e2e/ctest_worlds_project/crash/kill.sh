#!/bin/sh
# Tells the world's server on port $1 to die, then waits to be stopped by its collapse.
/usr/bin/python3 -c "import socket, sys; socket.create_connection(('127.0.0.1', int(sys.argv[1])), 5).sendall(b'die')" "$1"
exec sleep 30
