// DAP booting the board itself, as it did before it went through Session::boot: refused.
void load_program(Machine& m, SymbolTable& symbols, const Firmware& rom) {
    m.load(rom.segments);
    symbols.add_table(rom.symbols);
    LoadedImage img = load_image(m, path, lo);
    m.reset();
    t = schedule_press(m, k.kind, k.key, kKeyHold, kKeyGap, t);
}
