file(REMOVE_RECURSE
  "libfleetmap_common.a"
)
