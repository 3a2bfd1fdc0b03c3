#!/bin/bash
# The words bash would offer for a command line: complete_words.sh COMPLETION_FILE WORD...
# (the last WORD is the one being completed; bash-completion must be installed).
completion=$1; shift
source /usr/share/bash-completion/bash_completion
source "$completion"
COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
_alp85
printf "%s\n" "${COMPREPLY[@]}"
