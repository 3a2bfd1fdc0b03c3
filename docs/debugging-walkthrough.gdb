type R 7 0 8 0 0 EXEC
wait display "?.=----" timeout 200ms
type 0 0 1 2
wait display "H1=----" timeout 1s
type 0 1 0 0 EXEC 0 0 5 0 EXEC 0 3 0 0 EXEC 0 2 0 0 EXEC 0 7 5 0
info display
break OUT
press EXEC
bt
info registers
list
step 12
next
p YIDV
p word[YIDV] - word[YAC]
disassemble O42 6
advance O42+9
info 8155
step
bt
finish
delete 1
watch word YAC
display word[XAC]
display word[YAC]
continue
continue
info axis
history 6
reverse-step
reverse-continue
undisplay
delete
watch axis Y count
continue
delete
watch port F9H out == 03H
continue
info breakpoints
delete
break YID if word[XAC] == 110
continue
p word[YAC]
delete
break OUT
commands
p word[XAC]
continue
end
watch axis X steps if word[XAC] == 112
continue
delete
info 8279
x/16xb 1B00H
