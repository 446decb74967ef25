# Run by the 'book' target after Doxygen: the reader's check that nothing was left raw.
# A formula, snippet, image or reference command that Doxygen did not process shows up in
# the HTML as its source text (e.g. a "\f$" inside a construct Doxygen did not parse), and
# Doxygen does not always warn. Input: HTML (the html output directory).
file(GLOB pages ${HTML}/*.html)
set(bad "")
foreach(page ${pages})
  file(READ ${page} text)
  # Code listings of the source browser (*_source.html) quote comments verbatim; skip them.
  if(page MATCHES "_source\\.html$")
    continue()
  endif()
  foreach(cmd "\\f$" "\\f[" "\\f]" "\\snippet" "\\image" "\\htmlinclude" "\\ref ")
    string(FIND "${text}" "${cmd}" at)
    if(NOT at EQUAL -1)
      math(EXPR from "${at} - 60")
      if(from LESS 0)
        set(from 0)
      endif()
      string(SUBSTRING "${text}" ${from} 140 context)
      string(REPLACE "\n" " " context "${context}")
      get_filename_component(name ${page} NAME)
      string(APPEND bad "  ${name}: raw '${cmd}' near: ${context}\n")
    endif()
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "The book shows unprocessed Doxygen commands (unrendered formulas etc.):\n${bad}")
endif()
