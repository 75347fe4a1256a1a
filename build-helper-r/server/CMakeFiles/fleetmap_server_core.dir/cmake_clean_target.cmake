file(REMOVE_RECURSE
  "libfleetmap_server_core.a"
)
