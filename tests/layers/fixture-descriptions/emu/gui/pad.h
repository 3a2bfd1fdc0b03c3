enum class Pad : unsigned char { Matrix, Reset, Vect };  // a second copy of the board's key enum
