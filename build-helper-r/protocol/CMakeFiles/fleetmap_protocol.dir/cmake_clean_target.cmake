file(REMOVE_RECURSE
  "libfleetmap_protocol.a"
)
