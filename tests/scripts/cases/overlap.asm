; asm85 warns "overlapping ORG regions" at the second ORG's HLT (line 5, column 2).
	ORG 0800H
	NOP
	ORG 0800H
	HLT
