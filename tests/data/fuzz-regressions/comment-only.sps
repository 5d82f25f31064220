; empty file
