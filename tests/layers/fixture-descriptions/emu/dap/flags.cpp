// A front end with a flag table and a register switch of its own: what check_descriptions.cmake refuses.
constexpr struct {
    const char* name;
    unsigned bit;
} kFlags[] = {{"S", 0x80}, {"Z", 0x40}, {"AC", 0x10}, {"P", 0x04}, {"CY", 0x01}};

unsigned read(Reg r, const Registers& x) {
    switch (r) {
        case Reg::A: return x.a;
        case Reg::PSW: return x.a << 8 | x.f;
    }
    return 0;
}
