; Assembled at build time by alp85_assemble() and embedded by the test (embed_test.cpp).
	ORG	0E800H
ENTRY:	JMP	BODY
	DS	2
BODY:	MVI	C,9
	RET
	END	ENTRY
