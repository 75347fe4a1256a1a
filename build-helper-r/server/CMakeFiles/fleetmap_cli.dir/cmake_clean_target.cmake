file(REMOVE_RECURSE
  "libfleetmap_cli.a"
)
