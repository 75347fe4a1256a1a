// The integration tests' HTTP/WebSocket client of fleetmap-web (web_client.h): coming next.
