# Fish completion for ALP85's programs: alp85, asm85 and pisa-asm. As in alp85.bash, the commands
# and options are read from the program's own --help as it completes, so completion cannot drift
# from the program. Installed as share/fish/vendor_completions.d/{alp85,asm85,pisa-asm}.fish.

# The built-in firmware (alp85 run --firmware, debug, gui; tests/install checks this list).
function __alp85_firmware
    printf '%s\n' monitor thesis thesis-fixed master
end

# From a CLI11 --help text on stdin: its commands (name, tab, what); its options; those taking a value.
function __alp85_commands_in
    awk '/^Subcommands:/ { s = 1; next } s && /^  [a-z]/ { d = $0; sub(/^  [^ ]+ +/, "", d); print $1 "\t" d; next } s && !/^ / { s = 0 }'
end
function __alp85_options_in
    awk '/^ +-/ { n = split($1, a, ","); for (i = 1; i <= n; i++) if (a[i] ~ /^-/) print a[i] }'
end
function __alp85_valued_in
    awk '/^ +-/ && $2 ~ /^[A-Z]/ { n = split($1, a, ","); for (i = 1; i <= n; i++) if (a[i] ~ /^-/) print a[i] }'
end

# The commands typed after the program (alp85 bench cpu -> bench cpu), skipping options and values.
function __alp85_path
    set -l tokens (commandline -opc)
    set -l prog $tokens[1]
    set -l path
    set -l help ($prog --help 2>/dev/null)
    set -l skip 0
    for t in $tokens[2..-1]
        if test $skip = 1
            set skip 0
            continue
        end
        if string match -q -- '-*' $t
            contains -- $t (printf '%s\n' $help | __alp85_valued_in); and set skip 1
            continue
        end
        if contains -- $t (printf '%s\n' $help | __alp85_commands_in | string replace -r '\t.*' '')
            set -a path $t
            set help ($prog $path --help 2>/dev/null)
        end
    end
    set -q path[1]; and printf '%s\n' $path  # nothing at all for the program alone (not one empty word)
end
function __alp85_help
    set -l prog (commandline -opc)[1]
    $prog (__alp85_path) --help 2>/dev/null
end
# True when the word before the cursor is an option that takes a value (and is one of $argv, if any).
function __alp85_after_valued
    set -l prev (commandline -opc)[-1]
    string match -q -- '-*' $prev; or return 1
    contains -- $prev (__alp85_help | __alp85_valued_in); or return 1
    test (count $argv) -eq 0; or contains -- $prev $argv
end
# True when the command typed is one of $argv ("run", "bench cpu"; "" is the program alone).
function __alp85_command_is
    contains -- (string join ' ' (__alp85_path)) $argv
end

for prog in alp85 asm85 pisa-asm
    complete -c $prog -f
    complete -c $prog -n 'not __alp85_after_valued; and string match -q -- "-*" (commandline -ct)' -a '(__alp85_help | __alp85_options_in)'
    complete -c $prog -n '__alp85_after_valued --motor' -xa 'ideal physical'
    complete -c $prog -n '__alp85_after_valued --speed' -xa '0.1 1 10 100 max'
    complete -c $prog -n '__alp85_after_valued -I --include --out-dir' -xa '(__fish_complete_directories)'
    complete -c $prog -n '__alp85_after_valued; and not __alp85_after_valued --firmware --motor --speed --cpu -I --include --out-dir --keys --for --boot -D --define --from --to --org --bin-start --bin-end --fill --max-tstates --trace-last --port --seconds --name-length --click -j --jobs' -F
end
complete -c alp85 -n '__alp85_after_valued --firmware' -xa '(__alp85_firmware)'
complete -c alp85 -n '__alp85_after_valued --cpu' -xa '8080 8085'
complete -c asm85 -n '__alp85_after_valued --cpu' -xa '8080 8085 8085u'
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_help | string match -q "Subcommands:"' -a '(__alp85_help | __alp85_commands_in)'
# The commands' files, by kind.
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_command_is run debug gui' -a '(__alp85_firmware; __fish_complete_suffix .asm .hex .bin)'
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_command_is script' -a '(__fish_complete_suffix .alp)'
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_command_is cpm' -a '(__fish_complete_suffix .com .COM)'
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_command_is disasm' -a '(__fish_complete_suffix .hex .bin .com .asm)'
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_command_is gcode' -a '(__fish_complete_suffix .nc .ngc .gcode)'
complete -c alp85 -n 'not __alp85_after_valued; and __alp85_command_is pisa' -a '(__fish_complete_suffix .tape)'
complete -c asm85 -n 'not __alp85_after_valued' -a '(__fish_complete_suffix .asm .mac .inc .a85)'
complete -c pisa-asm -n 'not __alp85_after_valued' -a '(__fish_complete_suffix .pasm)'
