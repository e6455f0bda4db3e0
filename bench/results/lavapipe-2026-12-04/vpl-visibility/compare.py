# Mean-radiance ratio and relative RMS error of 8x8-block means of two PFM images: /usr/bin/python3 compare.py A.pfm B.pfm (numpy: Debian's python3-numpy)
import sys, numpy as np
def readpfm(p):
    f=open(p,'rb'); h=f.readline().strip(); w,hh=map(int,f.readline().split()); sc=float(f.readline())
    d=np.fromfile(f,dtype='<f4' if sc<0 else '>f4').reshape(hh,w,3 if h==b'PF' else 1)
    return np.flipud(d).astype(np.float64)
a=readpfm(sys.argv[1]); b=readpfm(sys.argv[2])
la=a.mean(axis=2); lb=b.mean(axis=2)
print('%s / %s: mean %.5g / %.5g = ratio %.4f' % (sys.argv[1], sys.argv[2], la.mean(), lb.mean(), la.mean()/max(lb.mean(),1e-30)))
H,W=la.shape; bs=8
ba=la[:H//bs*bs,:W//bs*bs].reshape(H//bs,bs,W//bs,bs).mean(axis=(1,3)); bb=lb[:H//bs*bs,:W//bs*bs].reshape(H//bs,bs,W//bs,bs).mean(axis=(1,3))
print('  8x8 block relative RMS error %.2f%%' % (100*np.sqrt(((ba-bb)**2).mean())/bb.mean()))
