# SPDX-License-Identifier: GPL-3.0-or-later
# Where scripts/setup.sh keeps what it fetches: $ELASTICA_CACHE_DIR, then
# ${XDG_CACHE_HOME}/elastica, then $HOME/.cache/elastica (in that order of preference).
function(elastica_cache_roots out)
  set(roots)
  if(DEFINED ENV{ELASTICA_CACHE_DIR})
    list(APPEND roots "$ENV{ELASTICA_CACHE_DIR}")
  endif()
  if(DEFINED ENV{XDG_CACHE_HOME})
    list(APPEND roots "$ENV{XDG_CACHE_HOME}/elastica")
  endif()
  if(DEFINED ENV{HOME})
    list(APPEND roots "$ENV{HOME}/.cache/elastica")
  endif()
  set(${out} "${roots}" PARENT_SCOPE)
endfunction()
