enum class Button : unsigned char { Matrix, Reset, Vect };
