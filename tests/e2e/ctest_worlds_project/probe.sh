#!/bin/sh
# A test: connects to 127.0.0.1:$1 (the world's server); passes when something answers.
exec /usr/bin/python3 -c "import socket, sys; socket.create_connection(('127.0.0.1', int(sys.argv[1])), 5); print('connected to', sys.argv[1])" "$1"
