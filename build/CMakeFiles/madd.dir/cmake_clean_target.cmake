file(REMOVE_RECURSE
  "libmadd.a"
)
