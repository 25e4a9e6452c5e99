"""Serves 127.0.0.1:PORT; exits with status 3 when a client sends b"die"."""
import socket
import sys

server = socket.create_server(("127.0.0.1", int(sys.argv[1])))
while True:
    client, _ = server.accept()
    if client.recv(16) == b"die":
        print("told to die")
        sys.exit(3)
    client.close()
