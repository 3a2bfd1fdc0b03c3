# GTKWave (--script) on the thesis's recording with docs/signals/thesis.gtkw: finds port A's first
# X pulse as GTKWave reads the file, prints its edges ("PULSE RISE FALL", ns), shows three steps
# from just before it with the baseline marker on the rising edge and the marker on the falling one
# (GTKWave writes their difference), grabs the window to $env(ALP85_SHOT) and quits.
set changes [gtkwave::signalChangeList alp85.i8155.PA0 -max 64]
set rise -1
set fall -1
foreach {t v} $changes {
    if {$rise < 0 && $v == 1} { set rise $t } elseif {$rise >= 0 && $v == 0} { set fall $t; break }
}
if {$rise < 0 || $fall < 0} {
    puts "NO PULSE on PA0: $changes"
    gtkwave::/File/Quit
}
set next -1
foreach {t v} $changes {
    if {$t > $fall && $v == 1} { set next $t; break }
}
puts "PULSE $rise $fall"
puts "NEXT $next"
set period [expr {$next > 0 ? $next - $rise : 4 * ($fall - $rise)}]
gtkwave::setZoomRangeTimes [expr {$rise - $period / 4}] [expr {$rise + 3 * $period - $period / 4}]
gtkwave::setBaselineMarker $rise
gtkwave::setMarker $fall
gtkwave::/File/Grab_To_File $env(ALP85_SHOT)
gtkwave::/File/Quit
