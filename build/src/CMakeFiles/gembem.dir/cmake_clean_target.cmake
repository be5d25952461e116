file(REMOVE_RECURSE
  "libgembem.a"
)
