# write-if-changed.cmake: write_if_changed(PATH TEXT) writes TEXT to PATH only when it differs
# from what PATH holds, so that a generated source rebuilds nothing when it did not change.
# Included by the scripts that generate sources at build time (git-commit.cmake,
# embed-sources.cmake).
function(write_if_changed path text)
  set(old "")
  if(EXISTS "${path}")
    file(READ "${path}" old)
  endif()
  if(NOT old STREQUAL text)
    file(WRITE "${path}" "${text}")
  endif()
endfunction()
